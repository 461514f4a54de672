// A run described as data: what `cdvp run` and `cdvp bullet` parse their
// command lines into, what a sweep's points and the Python module build, and
// what run() (sw/run/run.h) takes. Nothing here spells a command-line flag:
// to_arguments (sw/run/run_arguments.h) is the one place that does, for a
// run in a child process, and SettingNames (platform/settings) words every
// message in the face's own names.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "platform/settings/setting_values.h"

namespace cdvp {

// Where a run's settings come from besides the defaults, each layer over the
// last: a board preset, a settings file, NAME=VALUE overrides, then values
// given typed (the command line's dedicated flags, Python's keywords).
struct SettingLayers {
    std::optional<std::string> board;      // a preset's name, or a .json path
    std::optional<std::string> config;     // a settings file, JSON or (.toml) TOML
    std::vector<std::string> overrides;    // "NAME=VALUE", in order
    std::vector<Assignment> given;         // typed values over every other layer, origin kGiven
    // How every message and the report name a setting (the face's words).
    std::shared_ptr<const SettingNames> names = dotted_setting_names();
};

// The frames of a run.
struct TraceFrames {  // a trace CSV, or a pipe (copied once, so it can be read again)
    std::string path;
};
struct SceneFrames {  // a generated scene: "spheres" (the paper's application), a kinematic family
                      // ("pile", "heavy", "planar", "brownian") or one of Bullet's, replayed
    std::string name;
};
// A Bullet scene stepped in a btDiscreteDynamicsWorld with the board as its
// broad phase, beside the same scene on one of Bullet's own (`software`:
// simple, sap or dbvt), whose times the report's "bullet" section compares.
struct BulletWorlds {
    std::string name;
    std::string software = "dbvt";
};
using FrameInput = std::variant<TraceFrames, SceneFrames, BulletWorlds>;

// Waveforms of the board (the clocked engine or the RTL).
struct WaveRequest {
    std::string path;                    // the dump: a VCD, or an FST
    std::optional<std::string> frames;   // "A:B": only frames A to B as the run numbers them
    std::optional<std::string> format;   // "vcd" or "fst"; none: vcd
};

// What a run writes: every file or none (sw/output).
struct RunOutputs {
    std::optional<std::string> pairs_csv;  // frame,a,b
    std::optional<std::string> report;     // the JSON report
    std::optional<WaveRequest> waves;
    bool summary = true;                   // the summary on standard output; false: quiet
};

struct RunSpec {
    SettingLayers settings;
    std::optional<FrameInput> frames;      // none: refused, naming what to give
    std::vector<std::string> baselines;    // software broad phases to time: sap, dbvt, brute, soa
    // A directory of shared software timings (sw/run/software_timing.h): a
    // timing of this run's workload there is taken and nothing is timed.
    std::optional<std::string> software_timings;
    std::vector<std::string> faults;       // KIND@frame=N[,n=K] (docs/faults.md)
    RunOutputs outputs;
    // The command line the report records ("cdvp", "run", ...); empty: the
    // face's words for this spec (to_arguments).
    std::vector<std::string> command_line;
};

// "run" for a spec of trace or scene frames, "bullet" for Bullet's worlds:
// the cdvp command a child runs it with.
const char* command_of(const RunSpec& spec);

}  // namespace cdvp
