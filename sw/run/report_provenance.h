// What a report says about where its software times come from: the machine
// and its load, the build, the host profile, and the factors to the modelled
// host. `cdvp run` and `cdvp bullet` put both objects in their config, so a
// sweep's rows carry them as config.provenance.* and config.host_calibration.*.
#pragma once

#include <array>

#include <nlohmann/json.hpp>

#include "sw/run/host_factor.h"
#include "sw/run/machine_info.h"

namespace cdvp {

// The machine, its load average at the start, the cores, the compiler and
// flags, the version and commit, and the host profile used ({path, sha256}
// or "uncalibrated", "unstated", "overridden").
nlohmann::json provenance_json(const MachineInfo& machine, const std::array<double, 3>& load_start,
                               const HostTiming& host);

// How native time becomes modelled-host time: the basis, the factors, the
// preset's uncalibrated factor, and the profile's machine.
nlohmann::json host_calibration_json(const HostTiming& host);

// [1, 5, 15-minute load averages] as a JSON array.
nlohmann::json load_json(const std::array<double, 3>& loads);

}  // namespace cdvp
