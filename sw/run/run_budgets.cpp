#include "sw/run/run_budgets.h"

#include <algorithm>

#include "models/common/user_text.h"
#include "models/common/number_text.h"
#include "models/control_registers/control_registers.h"
#include "platform/memory_plan.h"
#include "sw/run/run_checks.h"
#include "platform/driver/frame_time.h"

namespace cdvp {

namespace {

// The largest pair budget: more than a frame of the address map's boxes can hold.
constexpr uint64_t kMaxPairBudget = uint64_t{1} << 43;

std::string count_text(uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

RunBudgets::RunBudgets(const SettingValues& values, const PlatformConfig& platform, BudgetShape shape,
                       FrameOrigin origin, MachineMemory machine)
    : values_(values), platform_(platform), shape_(std::move(shape)), origin_(std::move(origin)), machine_(machine) {
    const Setting& max_memory = declared_setting("run.max_memory");
    const uint64_t mib = values_.settings().run.max_memory_mib;
    const uint64_t least = machine_.least();
    if (mib == 0) {
        memory_bytes_ = least / 2 / machine_.sharing;
        memory_origin_ = (values_.is_default(max_memory) ? values_.origin_text(max_memory)
                                                         : values_.value_and_origin(max_memory)) +
                         ": half of " + machine_.describe_least() +
                         (machine_.sharing > 1 ? ", shared by " + std::to_string(machine_.sharing) + " runs at once"
                                               : std::string());
    } else {
        memory_bytes_ = mib << 20;
        memory_origin_ = values_.value_and_origin(max_memory);
        if (least != 0 && memory_bytes_ > least) {
            throw InputError(values_.where(max_memory) + ": a memory budget of " + size_text(memory_bytes_) +
                             " is more than " + machine_.describe_least() + "; expected at most " +
                             std::to_string(least >> 20) + " MiB (0: half of it)");
        }
    }
    if (const uint64_t program = program_bytes(shape_); memory_bytes_ <= program) {
        throw InputError(values_.where(max_memory) + ": the memory budget of " + size_text(memory_bytes_) + " (" +
                         memory_origin_ + ") is too little for the program itself: it needs an estimated " +
                         size_text(program) + " before any scene; give a larger " + named("run.max_memory"));
    }
}

// What the memory budget holds beyond the program, at `bytes` each.
TraceLimits RunBudgets::trace_limits() const {
    const uint64_t program = program_bytes(shape_);
    const uint64_t room = memory_bytes_ > program ? memory_bytes_ - program : 0;
    const auto held = [&](uint64_t bytes, const char* what) {
        return "what the memory budget of " + size_text(memory_bytes_) + " (" + memory_origin_ + ") holds at " +
               std::to_string(bytes) + " bytes " + what;
    };
    TraceLimits limits{address_map::kMaxObjects, "the board's address map"};
    if (const uint64_t boxes = room / bytes_per_box(shape_); boxes < address_map::kMaxObjects) {
        limits = TraceLimits{static_cast<std::size_t>(boxes), held(bytes_per_box(shape_), "a box")};
    }
    limits.max_frames = room / bytes_per_frame(shape_);
    limits.frames_reason = held(bytes_per_frame(shape_), "a frame");
    return limits;
}

InputLimits spooled_trace_limits() {
    const Setting& size = declared_setting("run.max_trace_size");
    InputLimits limits;
    limits.max_bytes = std::get<uint64_t>(size.default_value()) << 20;
    limits.max_bytes_origin = to_text(size.default_value()) + " MiB (the default of --" + size.flag + ")";
    return limits;
}

InputLimits RunBudgets::input_limits() const {
    InputLimits limits;
    limits.max_bytes = values_.settings().run.max_trace_mib << 20;
    limits.max_bytes_origin = values_.value_and_origin(declared_setting("run.max_trace_size"));
    return limits;
}

std::string RunBudgets::objects_text(uint64_t max_objects) const {
    return objects_origin(origin_, values_, max_objects);
}

std::string RunBudgets::frames_text(uint64_t frames) const {
    return count_text(frames, "frame", "frames") + " (" + frames_origin(origin_, values_) + ")";
}

std::string RunBudgets::pairs_origin() const {
    const Setting& max_pairs = declared_setting("run.max_pairs");
    if (values_.settings().run.max_pairs != 0) return values_.value_and_origin(max_pairs);
    return (values_.is_default(max_pairs) ? values_.origin_text(max_pairs) : values_.value_and_origin(max_pairs)) +
           ": what the memory budget of " + size_text(memory_bytes_) + " leaves, at " +
           std::to_string(footprint_.per_pair) + " bytes a pair";
}

void RunBudgets::check_scene(uint64_t max_objects, uint64_t frames) {
    shape_.board = planned_board(values_.settings(), max_objects);
    check_memory(max_objects, frames);
    check_time(max_objects, frames);
}

void RunBudgets::check_memory(uint64_t max_objects, uint64_t frames) {
    footprint_ = estimate_footprint(shape_, max_objects, frames);
    const Footprint& f = footprint_;
    const std::string budget = "the memory budget of " + size_text(memory_bytes_) + " (" + memory_origin_ + ")";
    if (f.before_pairs() > memory_bytes_) {
        const std::string model = shape_.clocked ? ", the board model's block RAM words at " +
                                                       values_.value_and_origin(declared_setting("board.m")) + " " +
                                                       size_text(f.model)
                                                 : "";
        throw InputError(values_.where(declared_setting("run.max_memory")) + ": " + budget + " is too little for " +
                         objects_text(max_objects) + " in " + frames_text(frames) + ": they need an estimated " +
                         size_text(f.before_pairs()) + " before any pair (the boxes " + size_text(f.boxes) + model +
                         ", the frames " + size_text(f.frames) + ", the program " + size_text(f.program) +
                         "); use fewer objects or frames, fewer baselines" + (shape_.clocked ? ", a smaller m" : "") +
                         ", or a larger " + named("run.max_memory"));
    }
    const uint64_t asked = values_.settings().run.max_pairs;
    if (asked == 0) {
        pairs_ = std::min((memory_bytes_ - f.before_pairs()) / f.per_pair, kMaxPairBudget);
        return;
    }
    pairs_ = asked;
    if (f.with_pairs(asked) > memory_bytes_) {
        throw InputError(values_.where(declared_setting("run.max_pairs")) + ": " + std::to_string(asked) +
                         " pairs a frame at " + std::to_string(f.per_pair) + " bytes a pair need an estimated " +
                         size_text(f.with_pairs(asked) - f.before_pairs()) + ", and the rest of the run " +
                         size_text(f.before_pairs()) + " for " + objects_text(max_objects) + ": more than " + budget +
                         "; give a smaller " + named("run.max_pairs") + " (0: what the budget leaves) or a larger " +
                         named("run.max_memory"));
    }
}

// Each frame at most as long as the driver's bounds allow with the frame's
// pairs at most the pair budget (and no more than its boxes can make); each
// injected fault may stretch a wait to its whole timeout; and the last wait's
// deadline may lie a whole timeout past the last frame.
void RunBudgets::check_time(uint64_t max_objects, uint64_t frames) const {
    const BoardConfig& board = shape_.board;
    const IdealBusTiming ideal;
    const BusTiming& bus = platform_.bus ? *platform_.bus : ideal;
    FrameTime time(platform_.driver, bus, fs_from_ns(1000.0 / board.clock_mhz), board.m,
                   board.collector.buffer_depth, board.tiles, platform_.quantum_ns);
    if (board.grid_board()) time.set_grid(board.grid);
    const auto n = static_cast<uint32_t>(max_objects);
    // Refused up front: a run that passes the limit even if no frame had a
    // pair. How many pairs the frames will have is not known before they run;
    // assuming the pair budget's worth in every frame would refuse runs that
    // take a small part of the limit. A run whose pairs take it past the limit
    // is stopped by the driver at the wait that would pass it, with this limit
    // in its message, before the kernel's clock could overflow.
    const double frame_ns = time.frame_bound_ns(n, 0);
    const double timeout_ns = time.longest_timeout_ns(n);
    double faults = 0;
    for (const FaultSpec& spec : platform_.faults) faults += static_cast<double>(std::min<uint64_t>(spec.count, time.waits(0)));
    const double total_ns = static_cast<double>(frames) * frame_ns + (faults + 1) * timeout_ns;
    const double limit_ns = ns_from_fs(kSimulatedTimeLimit);
    if (total_ns <= limit_ns) return;
    const auto [total_s, limit_s] = distinct_figures(total_ns * 1e-9, limit_ns * 1e-9, 3);
    throw InputError("a run of " + frames_text(frames) + " of up to " + objects_text(max_objects) + " at " +
                     values_.value_and_origin(declared_setting("board.m")) + " and " +
                     values_.value_and_origin(declared_setting("board.clock_mhz")) + " would reach " +
                     total_s + " s of simulated time (up to " + simulated_seconds(frame_ns) +
                     " a frame before any pair, and the deadline of its longest wait " +
                     simulated_seconds(timeout_ns) + " later), past the limit of " + limit_s + " s" +
                     " (2^63 fs, half SystemC's 64-bit femtosecond clock): use fewer objects or frames, or a larger m");
}

std::string RunBudgets::named(const char* name) const { return values_.names().named(declared_setting(name)); }

std::string RunBudgets::pair_budget_refusal(uint64_t frame, uint64_t found) const {
    return "frame " + std::to_string(frame) + ": " + std::to_string(found) + " pairs found, more than the pair budget of " +
           std::to_string(pairs_) + " (" + pairs_origin() +
           "); expected at most that many pairs a frame: give a larger " + named("run.max_pairs") + " or " +
           named("run.max_memory") + ", or a scene whose boxes overlap less";
}

}  // namespace cdvp
