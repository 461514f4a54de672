// The checks `cdvp run` makes before any work: board settings against each
// other, the scene against the board's block RAMs, this machine's memory and
// SystemC's time, and the --inject specs against the driver and the frames.
// Every message names where each value came from: a flag, its default, the
// preset's or config file's key, a -c, or the trace.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "models/common/fault_plan.h"
#include "platform/setting_values.h"
#include "sw/cli/run_options.h"
#include "sw/driver/board_driver.h"

namespace cdvp {

// A path longer than the system's PATH_MAX can name no file; refused quoting
// its start, so that no later message repeats it whole. Throws InputError.
void check_path_lengths(const RunOptions& o, const boost::program_options::variables_map& vm);

// The --inject specs; a fault the driver's mode can never meet is refused
// rather than silently never injected. Throws InputError.
std::vector<FaultSpec> fault_specs(const std::vector<std::string>& texts, const DriverConfig& driver);

// A spec for a frame the run never reaches is refused too. 'last_frame' is
// the run's last frame number (nothing: the run has no frames), 'has_frame'
// whether a number up to it is one of the run's frames (a trace may skip
// numbers), 'frames_origin' what numbers them ("--frames 4", "--trace FILE").
// Throws InputError.
void check_inject_frames(const std::vector<FaultSpec>& specs, std::optional<uint64_t> last_frame,
                         const std::function<bool(uint64_t)>& has_frame, const std::string& frames_origin);

// The scene must fit this machine's memory, SystemC's time and, unless
// run.ignore_capacity, the device: its block RAMs (device.block_rams, 0:
// unbounded) and, with a device family, the LUTs and flip-flops the
// synthesis-backed resource model gives the board. Throws InputError naming
// the resource and the largest m that fits.
void check_scene_fits(const RunOptions& o, const SettingValues& values, uint64_t max_objects, uint64_t frame_count);

}  // namespace cdvp
