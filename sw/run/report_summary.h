// The "summary" section of a run's report, typed: the one definition of its
// keys, written by the run (ReportWriter::end) and read back by the commands
// that run `cdvp run` as a child (sweep, fidelity). docs/formats.md: the report.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "models/energy/energy_model.h"
#include "sw/run/extra_pairs.h"
#include "sw/timing/spread.h"
#include "sw/timing/timing_quality.h"

namespace cdvp {

// One software baseline over the timed frames of every --repeat run.
struct BaselineSummary {
    Spread native_ns;  // CPU time measured on this machine (mean: the median of the runs' means)
    Spread wall_native_ns;  // the wall time beside it
    Spread host_ns;    // native_ns x host_factor: on the modelled host
    std::vector<double> run_means_native_ns;
    double host_factor = 1.0;
    double speedup = 0.0;  // host_ns.mean over the board's mean frame time
    // Energy a frame on the modelled host (host.package_w x host_ns.mean),
    // a pair, and over the board's (above 1: the board takes less).
    double energy_j = 0.0;
    double energy_per_pair_j = 0.0;
    double energy_ratio = 0.0;
    // This machine's package energy a frame, measured (RAPL); < 0: none to read.
    double native_energy_j = -1.0;
    TimingQuality quality;
    // Frames timed again: {run, frame, native_ns} each (run and frame from 0),
    // the figures' values where a report's frames hold the first try's.
    std::vector<std::array<double, 3>> retimed;
    // The software timing the figures were taken from when it was not this
    // run's own (a sweep's shared timing of the workload); empty: the run's.
    std::string timing;
};

struct ReportSummary {
    static constexpr std::size_t kPhases = 7;
    // The phases' keys in frames and, with mean_, here (simulated time).
    static const std::array<const char*, kPhases> kPhaseKeys;

    uint64_t frames = 0;
    uint64_t warmup_frames = 0;
    uint64_t frames_in_means = 0;  // the frames after the warm-up (all of them if no more)
    bool too_few_frames = false;   // the means rest on fewer frames than a figure should
    std::map<std::string, BaselineSummary> baselines;
    // The baseline with the least mean frame time on the modelled host (the
    // software the board is held to; sw/run/best_software.h); empty: none timed.
    std::string best_software;
    TimingQuality timing_quality;  // the baselines' together
    uint32_t retime_tries = 0;     // run.retime_tries: the tries a disturbed frame was given
    uint64_t pairs = 0;
    std::array<double, 3> load_average_end{};  // 1, 5 and 15 minutes, when the run ended
    ExtraPairs extra;  // against the float32 reference
    Spread total_ns;   // the board's simulated frame time (pipelined: the host's time a frame)
    Spread latency_ns; // a frame's from its upload to its pairs (one frame at a time: total_ns)
    Spread sim_wall_native_ns;  // the simulator's own wall time per frame
    std::array<double, kPhases> mean_phase_ns{};  // upload .. total, means over frames_in_means
    // The board's energy a frame by part, and a pair, over frames_in_means;
    // the host's package power behind the host part and the software's.
    FrameEnergy mean_energy;
    double mean_energy_per_pair_j = 0.0;
    double host_package_w = 0.0;
    // The board ran at a clock beyond its estimated Fmax (run.ignore_timing):
    // the refusal it would otherwise have had, in one line. Empty: none.
    std::string timing_warning;
};

nlohmann::json to_json(const ReportSummary& summary);
nlohmann::json to_json(const TimingQuality& quality);
// `where` names the timing quality itself ("t.json: baselines.sap.timing_quality");
// throws InputError "WHERE.KEY: expected ..., got ..." for the first key
// missing or out of its range (sw/run/json_fields.h): counts whole and
// fitting their type, runs at least 1, the probe's time finite from 0 to
// kMaxTimeNs, the spread and the loads finite and not negative.
TimingQuality timing_quality_from_json(const nlohmann::json& json, const std::string& where);
// Throws InputError naming `source` and the first key missing or mistyped.
ReportSummary summary_from_json(const nlohmann::json& summary, const std::string& source);

}  // namespace cdvp
