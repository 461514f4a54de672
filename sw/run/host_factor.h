// How a run turns native software time into time on the modelled host. A
// preset states its host's times on the reference workload; a host profile
// gives this machine's; their ratio is the host factor, one per baseline of
// the workload and their geometric mean for all other software. Without a
// profile the preset's speed_factor stands in (uncalibrated), and a
// --host-factor given by the user overrides all of it.
#pragma once

#include <array>
#include <map>
#include <string>

#include "platform/settings/setting_values.h"
#include "sw/run/host_profile.h"

namespace cdvp {

struct HostTiming {
    enum class Basis {
        kCalibrated,    // a host profile and the preset's reference times
        kUncalibrated,  // the preset states reference times, but no profile was found
        kUnstated,      // the host states no reference times (no preset): speed_factor
        kOverridden,    // --host-factor (or -c, a config file) sets the factor
    };
    Basis basis = Basis::kUnstated;
    std::string host = "this machine";
    double uncalibrated_factor = 1;         // the preset's speed_factor
    std::map<std::string, double> factors;  // calibrated: per baseline of the reference workload
    double overall = 1;                     // every other software time (Bullet's step, say)
    std::string profile_path;               // the profile looked for (calibrated: read)
    std::string profile_sha256;             // calibrated: of the file read
    std::string profile_machine;            // calibrated: the CPU it was taken on, and when
    double profile_spread = 0;              // calibrated: the profile's worst spread of its kept runs
    double profile_target_spread = 0;       // and what it was calibrated for
    std::array<double, 3> profile_load{};   // the load as it began
    double probe_reference_ns = 0;          // calibrated: the machine's fast speed (SpeedProbe), 0: none
    bool profile_poor() const { return basis == Basis::kCalibrated && profile_spread > profile_target_spread; }

    // The factor for a baseline's times: its own when calibrated, else overall.
    double factor(const std::string& baseline) const;
    const char* basis_name() const;  // "calibrated", "uncalibrated", "unstated", "overridden"
    // One line for the summary: "native x 4 (the preset's uncalibrated estimate)".
    std::string describe() const;
};

// The modelled host's reference time for a baseline (0: not stated).
double host_reference_ns(const HostConfig& host, const std::string& baseline);

// Per baseline of the reference workload: the host's reference time over the
// profile's, for each baseline the host states a time for; and under
// "overall", their geometric mean.
std::map<std::string, double> derive_factors(const HostConfig& host, const HostProfile& profile);

// factor_given: host.speed_factor was set above the preset (a flag, -c, a
// config file). Reads host.profile if set (it must exist, else it is refused
// under profile_label), else the default location if a file is there. Throws
// InputError for a profile it refuses.
HostTiming resolve_host_timing(const HostConfig& host, bool factor_given,
                               const std::string& profile_label = "host.profile");
// The same for a run's layered settings: host.speed_factor counts as given
// when a config file, -c or --host-factor set it.
HostTiming resolve_host_timing(const SettingValues& values);

// The line a run prints on stderr when it falls back on the preset's
// uncalibrated factor, or rests on a poor profile; empty otherwise.
std::string uncalibrated_note(const HostTiming& timing);

}  // namespace cdvp
