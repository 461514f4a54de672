#include "sw/run/run_checks.h"

#include <limits.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "models/control_registers/control_registers.h"
#include "platform/device_fit.h"
#include "models/address_generator/sweep_schedule.h"
#include "platform/memory_plan.h"
#include "platform/fault_injection.h"
#include "models/common/user_text.h"
#include "models/rtl_engine/rtl_variant.h"
#include "sw/bullet/scenes.h"
#include "sw/run/generated_source.h"
#include "sw/scene/scene.h"

namespace cdvp {

namespace {

// How to run past the device's capacity, in the face's words: "--ignore-capacity".
std::string ignore_capacity(const SettingValues& values) {
    return values.names().setting_to(declared_setting("run.ignore_capacity"), "yes");
}

}  // namespace

std::string objects_origin(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects) {
    const std::string count = std::to_string(max_objects);
    const SettingNames& names = values.names();
    if (!origin.trace.empty()) {
        return count + " objects (the largest frame of " + names.input("trace") + " " + excerpt(origin.trace) + ")";
    }
    // A Bullet scene has more collision objects than the bodies it is built
    // around (a ground, walls, a ball): the boxes are what the board holds.
    if (is_bullet_scene(origin.scene)) {
        return count + " boxes (the collision objects of " + names.input("scene") + " " + origin.scene + " at " +
               values.value_and_origin(declared_setting("scene.objects")) + ")";
    }
    return count + " objects (" + values.origin_text(declared_setting("scene.objects")) + ")";
}

std::string frames_origin(const FrameOrigin& origin, const SettingValues& values) {
    return !origin.trace.empty() ? "the frames of " + values.names().input("trace") + " " + excerpt(origin.trace)
                                 : values.origin_text(declared_setting("scene.frames"));
}

void check_path_lengths(const std::vector<std::pair<const char*, const std::optional<std::string>*>>& paths,
                        const SettingNames& names) {
    for (const auto& [key, path] : paths) {
        if (!*path || (*path)->size() < PATH_MAX) continue;
        throw InputError(names.input(key) + ": expected a path of at most " + std::to_string(PATH_MAX - 1) +
                         " bytes, got '" + excerpt(**path) + "'");
    }
}

// A window of traced frames that starts after the run's last frame would
// trace nothing: refused, as a fault injected into such a frame is.
void check_trace_window(const std::pair<uint64_t, uint64_t>& window, std::optional<uint64_t> last,
                        const std::string& source, const SettingNames& names) {
    if (window.first == 0 && window.second == UINT64_MAX) return;
    if (!last || window.first > *last) {
        throw InputError(names.input("vcd-frames") + ": " + std::to_string(window.first) + ":" + std::to_string(window.second) +
                         (last ? " starts after the run's last frame " + std::to_string(*last)
                               : std::string(" asks for frames of a run with none")) +
                         " (" + excerpt(source) + ")");
    }
}

// A:B, frame numbers as the run numbers them.
std::pair<uint64_t, uint64_t> vcd_window(const std::optional<std::string>& frames, const SettingNames& names) {
    if (!frames) return {0, UINT64_MAX};
    const std::string& text = *frames;
    const std::size_t colon = text.find(':');
    auto number = [&](const std::string& digits, uint64_t& value) {
        if (digits.empty() || digits.size() > 19 || digits.find_first_not_of("0123456789") != std::string::npos) {
            return false;
        }
        value = std::stoull(digits);
        return true;
    };
    uint64_t first = 0, last = 0;
    if (colon == std::string::npos || !number(text.substr(0, colon), first) || !number(text.substr(colon + 1), last) ||
        first > last) {
        throw InputError(names.input("vcd-frames") + ": expected A:B, frame numbers with A <= B, got '" + excerpt(text) + "'");
    }
    return {first, last};
}

void check_frame_input(const std::optional<FrameInput>& frames, const SettingNames& names) {
    if (!frames) {
        throw InputError("give exactly one of " + names.input("trace") + " FILE or " + names.input("scene") + " NAME (" +
                         generated_scene_list() + ", or one of Bullet's)");
    }
    if (const auto* trace = std::get_if<TraceFrames>(&*frames)) {
        if (trace->path.empty()) throw InputError(names.input("trace") + ": expected a file path, got ''");
    } else if (const auto* scene = std::get_if<SceneFrames>(&*frames)) {
        if (!is_generated_scene(scene->name) && !is_bullet_scene(scene->name)) {
            throw InputError(names.input("scene") + ": expected " + generated_scene_list() + " or one of Bullet's scenes (" +
                             bullet_scene_list() + "), got '" + excerpt(scene->name) + "'");
        }
    }
}

SceneSpec bullet_scene_spec(const std::string& scene, const SettingValues& values) {
    const SceneSettings& settings = values.settings().scene;
    if (settings.objects < 1 || settings.objects > kMaxSceneObjects) {
        throw InputError(values.where(declared_setting("scene.objects")) + ": expected 1 to " + std::to_string(kMaxSceneObjects) +
                         " objects in Bullet's scene " + scene + ", got " + std::to_string(settings.objects));
    }
    return SceneSpec{scene, static_cast<uint32_t>(settings.objects), settings.seed};
}

// A trace brings its own objects and frames: scene.* settings go with a scene only.
void check_scene_settings(bool trace, const SettingValues& values) {
    if (!trace) return;
    for (const Setting* s : values.effective()) {
        if (s->section() == "scene" && !values.is_default(*s)) {
            throw InputError(values.where(*s) + " goes with " + values.names().input("scene") + ", not " +
                             values.names().input("trace"));
        }
    }
}

std::vector<FaultSpec> fault_specs(const std::vector<std::string>& texts, const DriverConfig& driver,
                                   const SettingNames& names) {
    const std::string label = names.input("inject");
    std::vector<FaultSpec> specs;
    for (const std::string& text : texts) {
        std::vector<FaultSpec> parsed;
        try {
            parsed = parse_fault_specs(text);
        } catch (const InputError& e) {
            throw InputError(label + ": " + e.what());
        }
        for (const FaultSpec& spec : parsed) {
            const bool needs_dma = spec.kind == FaultKind::kTargetAbort || spec.kind == FaultKind::kMasterAbort ||
                                   spec.kind == FaultKind::kRetry || spec.kind == FaultKind::kDisconnect ||
                                   spec.kind == FaultKind::kDmaHang;
            if (needs_dma && driver.transfer != Transfer::kDma) {
                throw InputError(label + ": '" + to_string(spec) + "' faults a DMA; it needs " +
                                 names.setting_to(declared_setting("run.transfer"), "dma"));
            }
            if (spec.kind == FaultKind::kLostIrq && driver.wait != WaitMode::kIrq) {
                throw InputError(label + ": '" + to_string(spec) + "' loses an interrupt; it needs " +
                                 names.setting_to(declared_setting("run.wait"), "irq"));
            }
            specs.push_back(spec);
        }
    }
    return specs;
}

void check_inject_frames(const std::vector<FaultSpec>& specs, std::optional<uint64_t> last_frame,
                         const std::function<bool(uint64_t)>& has_frame, const std::string& frames_origin,
                         const SettingNames& names) {
    for (const FaultSpec& spec : specs) {
        const std::string prefix = names.input("inject") + ": '" + to_string(spec) + "': frame " + std::to_string(spec.frame);
        if (!last_frame) throw InputError(prefix + " never runs: the run has no frames (" + frames_origin + ")");
        if (spec.frame > *last_frame) {
            throw InputError(prefix + " is past the run's last frame " + std::to_string(*last_frame) + " (" +
                             frames_origin + ")");
        }
        if (!has_frame(spec.frame)) throw InputError(prefix + " is not one of the run's frames (" + frames_origin + ")");
    }
}

namespace {
// The first device resource the board overflows, as the error names it:
// the setting, its capacity and unit, and what the board needs.
struct Overflow {
    const char* setting;
    double available;
    double needed;
    const char* unit;
};

Overflow overflow_of(const DeviceFit& fit) {
    const Resources total = fit.resources.total();
    if (fit.use.overflow == "LUTs") return {"device.luts", fit.device.luts, total.luts, "LUTs"};
    if (fit.use.overflow == "flip-flops") return {"device.flip_flops", fit.device.flip_flops, total.flip_flops, "flip-flops"};
    return {"device.block_rams", fit.device.block_rams, total.block_rams, "block RAMs"};
}

std::string whole(double value) { return std::to_string(static_cast<uint64_t>(std::ceil(value))); }

// A board in SSRAM: the SSRAM holds the boxes, and the tiles are few enough
// to schedule (the model's bound, so --ignore-capacity does not lift it).
void check_ssram(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects, const MemoryPlan& plan) {
    const Settings& settings = values.settings();
    const std::string memory = values.value_and_origin(declared_setting("board.memory"));
    if (plan.ssram_capacity == 0) {
        throw InputError(values.where(declared_setting("device.ssram_banks")) + ": the device has no off-chip SSRAM (0 banks); " +
                         memory + " needs some: use block_ram or give device.ssram_banks");
    }
    if (!settings.run.ignore_capacity && max_objects > plan.ssram_capacity) {
        throw InputError(values.where(declared_setting("device.ssram_words")) + ": " + std::to_string(settings.device.ssram_words) +
                         " words a bank in " + std::to_string(settings.device.ssram_banks) + " SSRAM banks hold " +
                         std::to_string(plan.ssram_capacity) + " boxes, too few for " +
                         objects_origin(origin, values, max_objects) + " (" + memory +
                         "): use fewer objects; " + ignore_capacity(values) + " runs it anyway");
    }
    const uint64_t tiles = (max_objects + plan.tiles.boxes - 1) / plan.tiles.boxes;
    if (tiles > SweepSchedule::kMaxTiles) {
        throw InputError(values.where(declared_setting("board.tile_boxes")) + ": tiles of " + std::to_string(plan.tiles.boxes) +
                         " boxes make " + std::to_string(tiles) + " tiles of " + objects_origin(origin, values, max_objects) +
                         "; expected at most " + std::to_string(SweepSchedule::kMaxTiles) + " tiles: give larger tiles");
    }
}

// The tile buffers of a board in SSRAM do not fit the block RAMs.
[[noreturn]] void refuse_tile(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects,
                              const MemoryPlan& plan) {
    const Settings& settings = values.settings();
    BoardConfig board = planned_board(settings, max_objects);
    uint32_t largest = 0;  // the largest m whose buffers hold a tile of this size
    for (uint32_t m = 1; m <= BoardConfig::kMaxM; ++m) {
        board.m = m;
        if (board.block_rams(max_objects) <= settings.device.block_rams) largest = m;
    }
    board.m = settings.board.m;
    // The format's own layout: word groups a box, boxes a primitive.
    const BlockRamLayout layout = board.format.block_ram_layout(board.memory_depth(max_objects));
    throw InputError(values.where(declared_setting("device.block_rams")) + ": " + std::to_string(settings.device.block_rams) +
                     " block RAMs are too few for the SSRAM tile buffers of " +
                     values.value_and_origin(declared_setting("board.m")) + " at " + objects_origin(origin, values, max_objects) +
                     " in tiles of " + std::to_string(plan.tiles.boxes) + " boxes: they need " +
                     std::to_string(layout.word_groups()) + " x (2m+2) x ceil(T/" + std::to_string(layout.depth) +
                     ") = " + std::to_string(board.block_rams(max_objects)) +
                     (largest > 0 ? " (largest m that fits: " + std::to_string(largest)
                                  : " (not even m=1 fits: use smaller tiles or a larger device") +
                     "; " + ignore_capacity(values) + " runs it anyway)");
}

void check_device_fits(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects) {
    const Settings& settings = values.settings();
    if (settings.run.ignore_capacity) return;
    const MemoryPlan plan = plan_memory(settings, max_objects);
    const BoardConfig board = planned_board(settings, max_objects);
    const std::string m = values.value_and_origin(declared_setting("board.m"));
    const std::string at = m + " at " + objects_origin(origin, values, max_objects);
    const std::string explore = "; " + ignore_capacity(values) + " runs it anyway";
    // The coordinate memories alone: a check that needs no synthesis family.
    const uint32_t block_rams = settings.device.block_rams;
    const uint64_t needed = board.block_rams(max_objects);
    if (plan.ssram && !plan.tile_fits) refuse_tile(origin, values, max_objects, plan);
    if (block_rams != 0 && needed > block_rams) {
        // At a smaller m the boxes may fit, or move to SSRAM tiles (--memory auto).
        const uint64_t largest = largest_m_in_block_rams(settings, max_objects);
        throw InputError(values.where(declared_setting("device.block_rams")) + ": " + std::to_string(block_rams) +
                         " block RAMs are too few for " + at + ": they need " +
                         std::to_string(board.format.block_ram_layout(max_objects).word_groups()) + " x m x ceil(N/" +
                         std::to_string(board.format.block_ram_layout(max_objects).depth) + ")" +
                         (board.block_ram_banks() > 1 ? " x " + std::to_string(board.block_ram_banks()) + " box banks"
                                                      : std::string()) +
                         " = " + std::to_string(needed) +
                         (largest > 0 ? " (largest m that fits: " + std::to_string(largest) + explore + ")"
                                      : " (not even m=1 fits: use fewer objects or a larger device" + explore + ")"));
    }
    if (!has_device_family(settings)) return;
    const DeviceFit fit = fit_on_device(settings, max_objects);
    if (fit.use.fits()) return;
    const Overflow over = overflow_of(fit);
    throw InputError(values.where(declared_setting(over.setting)) + ": " + whole(over.available) + " " + over.unit +
                     " are too few for " + at + ": the board needs " + whole(over.needed) + " (" +
                     std::to_string(2 * board.m - 1) + " " + board.format.name() +
                     " lanes, the memories, address generator, pair FIFO "
                     "and control, from synthesis for " + name_of(settings.device.family) + ")" +
                     (fit.largest_m > 0 ? " (largest m that fits: " + std::to_string(fit.largest_m) + explore + ")"
                                        : " (not even m=1 fits" + explore + ")"));
}

}  // namespace

namespace {
// A full pair buffer's encoding must fit the 16 MiB pair window: a bitmap
// of more than 11,584 boxes, or per-row counts of a deep buffer on a tiled
// board, may not (the board would refuse START).
void check_pair_window(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects,
                       const MemoryPlan& plan) {
    const Settings& settings = values.settings();
    const PairFormat format = settings.driver.pair_format;
    const auto objects = static_cast<uint32_t>(max_objects);
    const uint64_t depth = settings.board.collector.buffer_depth;
    const uint64_t words = worst_encoded_words(format, depth, objects, settings.board.grid_board() ? 0 : plan.tiles.row_pieces(objects));
    const uint64_t window = address_map::kPairBufferSize / 4;
    if (words <= window) return;
    throw InputError(values.where(*find_setting("driver.pair_format")) + ": a full pair buffer of " +
                     std::to_string(depth) + " pairs (" + values.where(*find_setting("board.pair_buffer_depth")) +
                     ") at " + objects_origin(origin, values, max_objects) + " can encode to " +
                     std::to_string(words) + " words, more than the pair window's " + std::to_string(window) +
                     "; expected a smaller scene or buffer, or " +
                     values.names().setting_to(*find_setting("driver.pair_format"), "list"));
}
}  // namespace

namespace {
// The rtl level runs only the parameter sets compiled in (models/rtl_engine):
// one that is not is refused before anything is elaborated.
void check_rtl_built(const FrameOrigin& origin, const SettingValues& values, uint64_t max_objects) {
    if (values.settings().run.fidelity != ModelLevel::kRtl) return;
    try {
        rtl_variant_for(planned_board(values.settings(), max_objects), static_cast<uint32_t>(max_objects));
    } catch (const std::invalid_argument& e) {
        throw InputError(values.value_and_origin(declared_setting("run.fidelity")) + " at " +
                         objects_origin(origin, values, max_objects) + ": " + e.what());
    }
}
}  // namespace

std::optional<std::string> check_scene_fits(const FrameOrigin& origin, const SettingValues& values,
                                            uint64_t max_objects, uint64_t frame_count, RunBudgets& budgets) {
    check_rtl_built(origin, values, max_objects);
    const MemoryPlan plan = plan_memory(values.settings(), max_objects);
    check_pair_window(origin, values, max_objects, plan);
    if (plan.ssram) check_ssram(origin, values, max_objects, plan);
    check_grid_fits(values, max_objects, objects_origin(origin, values, max_objects));
    budgets.check_scene(max_objects, frame_count);
    std::optional<std::string> clock_warning = check_clock(values, max_objects);
    check_device_fits(origin, values, max_objects);
    return clock_warning;
}

}  // namespace cdvp
