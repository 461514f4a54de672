// The one fold of a run's settings into the platform they describe: every
// command that simulates on the platform (cdvp run, cdvp bullet, tests of
// presets) calls platform_config, so a setting means the same to each.
#pragma once

#include "platform/settings/setting_values.h"
#include "platform/virtual_board.h"

namespace cdvp {

// The board (its settings checked against each other), the bus (null for the
// ideal one), the driver with its run.transfer and run.wait, the engine
// (run.fidelity) and the host CPU's quantum (run.quantum_ns). Throws
// InputError naming where a failing value came from. What the settings do
// not hold is the caller's: faults to inject, the pair budget, and the
// board's tiles, which plan_memory (platform/memory_plan.h) plans for the
// boxes a run holds.
PlatformConfig platform_config(const SettingValues& values);

}  // namespace cdvp
