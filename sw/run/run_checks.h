// The checks a run makes before any work: board settings against each
// other, the scene against the board's block RAMs and the run's budgets
// (sw/run/run_budgets.h), and the faults to inject against the driver and the
// frames. Every message names where each value came from, in the face's
// words (SettingNames): a flag, its default, the preset's or config file's
// key, an override, or the trace.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "models/common/fault_plan.h"
#include "platform/settings/setting_values.h"
#include "sw/run/run_budgets.h"
#include "sw/run/run_spec.h"
#include "platform/driver/board_driver.h"

namespace cdvp {

struct SceneSpec;

// A path longer than the system's PATH_MAX can name no file; refused quoting
// its start, so that no later message repeats it whole. paths: each input's
// key ("trace", "report") and its value, checked when given. Throws InputError.
void check_path_lengths(const std::vector<std::pair<const char*, const std::optional<std::string>*>>& paths,
                        const SettingNames& names);

// Frames from a trace (a path) or a generated scene: spheres, a kinematic
// family (pile, heavy, planar, brownian), or one of Bullet's scenes as cdvp
// record records it. Throws InputError.
void check_frame_input(const std::optional<FrameInput>& frames, const SettingNames& names);
// One of Bullet's scenes (--scene NAME) as the settings give it: refused,
// naming where the count came from, outside 1 to kMaxSceneObjects objects.
// Throws InputError.
SceneSpec bullet_scene_spec(const std::string& scene, const SettingValues& values);
// A trace brings its own objects and frames: scene.* settings go with a
// generated scene only. Throws InputError.
void check_scene_settings(bool trace, const SettingValues& values);

// The traced frames' window "A:B", frame numbers as the run numbers them (0
// to 2^64-1 without one). Throws InputError.
std::pair<uint64_t, uint64_t> vcd_window(const std::optional<std::string>& frames, const SettingNames& names);
// A window that starts after the run's last frame (nothing: no frames) would
// trace nothing: refused, as a fault injected into such a frame is. Throws InputError.
void check_trace_window(const std::pair<uint64_t, uint64_t>& window, std::optional<uint64_t> last,
                        const std::string& source, const SettingNames& names);

// The faults to inject; a fault the driver's mode can never meet is refused
// rather than silently never injected. Throws InputError.
std::vector<FaultSpec> fault_specs(const std::vector<std::string>& texts, const DriverConfig& driver,
                                   const SettingNames& names);

// A spec for a frame the run never reaches is refused too. 'last_frame' is
// the run's last frame number (nothing: the run has no frames), 'has_frame'
// whether a number up to it is one of the run's frames (a trace may skip
// numbers), 'frames_origin' what numbers them ("--frames 4", "--trace FILE").
// Throws InputError.
void check_inject_frames(const std::vector<FaultSpec>& specs, std::optional<uint64_t> last_frame,
                         const std::function<bool(uint64_t)>& has_frame, const std::string& frames_origin,
                         const SettingNames& names);

// The scene must fit its memory (block RAM or SSRAM tiles), the run's
// budgets (memory, pairs and simulated time: RunBudgets::check_scene) and,
// unless run.ignore_capacity, the device: its block RAMs (device.block_rams,
// 0: unbounded) and, with a device family, the LUTs and flip-flops the
// synthesis-backed resource model gives the board. Throws InputError naming
// the resource and the largest m that fits. A board clock beyond the
// device's estimated Fmax is refused, or with run.ignore_timing returned as
// a warning for the run's observer.
std::optional<std::string> check_scene_fits(const FrameOrigin& origin, const SettingValues& values,
                                            uint64_t max_objects, uint64_t frame_count, RunBudgets& budgets);

// Where a run's counts came from, inside a sentence: "500 objects (the
// default of --objects)", "20 objects (the largest frame of --trace t.csv)",
// "3001 boxes (the collision objects of --scene boxes at 3000 objects (the
// default of --objects))"; "the frames of --trace t.csv", "--frames".
std::string objects_origin(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects);
std::string frames_origin(const FrameOrigin& origin, const SettingValues& values);

}  // namespace cdvp
