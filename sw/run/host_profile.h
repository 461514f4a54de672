// A host profile: what `cdvp calibrate` measured on a machine (the reference
// workload's times with their spread, the machine and the build) as JSON,
// and the reader a run uses, which refuses a damaged or foreign file on one
// line naming the file and the field.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "sw/run/build_info.h"
#include "sw/run/machine_info.h"

namespace cdvp {

// One baseline at one size: the mean frame time (thread CPU time) of each
// calibration run, the runs kept (the `repeat` whose means lie closest
// together: a run a neighbour disturbed falls outside them) and the median
// of the kept runs' means.
struct ReferenceTiming {
    uint64_t objects = 0;
    std::vector<double> run_means_native_ns;   // every run, in order
    std::vector<double> kept_means_native_ns;  // the closest `repeat` of them, ascending
    double mean_native_ns = 0;
    // max/min - 1 over the kept runs' means: how far repeats on this machine agree.
    double spread() const;
};

struct BaselineReference {
    std::vector<ReferenceTiming> sizes;  // one per reference_workload::objects()
    // The geometric mean of the sizes' mean_native_ns: the baseline's
    // reference time, against a preset's host.reference_NAME_ns.
    double reference_native_ns = 0;
};

struct HostProfile {
    std::string created;  // UTC, ISO 8601
    std::string sha256;   // of the file read_host_profile read
    MachineInfo machine;
    BuildInfo build;
    std::array<double, 3> load_average_start{}, load_average_end{};
    uint32_t repeat = 0;   // runs kept at each size
    uint32_t runs = 0;     // runs made before the kept ones agreed, or the time ran out
    double seconds = 0;    // the calibration's wall time
    double spread = 0;     // the worst ReferenceTiming::spread() of any baseline and size
    double target_spread = 0;  // what it repeated for (--max-spread)
    uint64_t disturbed_frames = 0;  // frames pre-empted or moved to another CPU while timed
    double probe_native_ns = 0;     // the machine's fast speed: SpeedProbe's 10th percentile
    // The spread stayed over the target: runs on this profile say so.
    bool poor() const { return spread > target_spread; }
    std::map<std::string, BaselineReference> reference;  // by baseline name
    // Informational: the factor to each preset's modelled host as derived when
    // calibrating (a run derives its own from its preset's reference times).
    std::map<std::string, std::map<std::string, double>> factors;
};

// The profile as JSON text (nlohmann's dump(2) and a line end).
std::string host_profile_json(const HostProfile& profile);

// Reads and checks a profile. Throws InputError "PATH: FIELD: what was
// expected", on one line, for a file that is not a profile of this
// reference workload (foreign) or whose fields are missing or out of range
// (damaged).
HostProfile read_host_profile(const std::string& path);
// The same for a profile's text already read from `path`.
HostProfile parse_host_profile(const std::string& path, const std::string& text);

// Where a run looks for a profile when --host-profile is not given and
// cdvp calibrate writes one without --out: $XDG_CONFIG_HOME/cdvp/host-profile.json,
// else $HOME/.config/cdvp/host-profile.json (each only an absolute path,
// user_base_directory); empty when neither is.
std::string default_host_profile_path();

}  // namespace cdvp
