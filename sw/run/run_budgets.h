// The budgets cdvp run is held to before any work (docs/numerics.md:
// "Budgets before work"): the memory it may hold (run.max_memory), the pairs a
// frame may hold (run.max_pairs), the simulated time it may reach (one limit,
// kSimulatedTimeLimit) and the size of its trace (run.max_trace_size). A run
// past one is refused with status 2 and one line naming each value and where
// it came from, before the scene is generated or simulated.
#pragma once

#include <cstdint>
#include <string>

#include "models/common/pair_budget.h"
#include "platform/settings/setting_values.h"
#include "platform/virtual_board.h"
#include "sw/run/machine_memory.h"
#include "sw/run/run_footprint.h"
#include "sw/scene/input_spool.h"
#include "sw/scene/trace_csv.h"

namespace cdvp {

// The limits a command that hands a piped trace on to its child runs copies
// it under: run.max_trace_size's default (each child holds the trace to the
// size it is given as it reads the copy).
InputLimits spooled_trace_limits();

// What a run's frames come from, as its refusals name it: a trace, or a
// generated scene.
struct FrameOrigin {
    std::string trace;  // --trace's path; empty for a generated scene
    std::string scene;  // --scene's name; empty for a trace
};

class RunBudgets {
public:
    // origin: the run's trace or scene. shape: what the run is (its board is
    // planned again for each scene checked). Throws InputError for a memory
    // budget past what this process may have.
    RunBudgets(const SettingValues& values, const PlatformConfig& platform, BudgetShape shape, FrameOrigin origin,
               MachineMemory machine = machine_memory());

    uint64_t memory_bytes() const { return memory_bytes_; }
    // "--max-memory 2048", "half of this machine's 24104 MiB of memory (the
    // default of --max-memory)".
    const std::string& memory_origin() const { return memory_origin_; }

    // Before a trace is read: the most boxes a frame may hold (the board's
    // address map, or fewer when the memory budget cannot hold more even
    // without the board model), the most frames it may have (each leaves a
    // number and a digest) and its largest size in bytes.
    TraceLimits trace_limits() const;
    InputLimits input_limits() const;

    // A scene of frames of up to max_objects boxes against the memory budget
    // (everything but the pairs, then the pair budget's pairs), and against
    // the simulated-time limit with the driver's own bounds on each frame and
    // wait (platform/driver/frame_time.h). Throws InputError. Sets pair_budget():
    // run.max_pairs, or what the memory budget leaves for pairs.
    void check_scene(uint64_t max_objects, uint64_t frames);

    PairBudget pair_budget() const { return PairBudget(pairs_); }
    const Footprint& footprint() const { return footprint_; }
    // The refusal of a frame whose pairs outgrew the budget, one line:
    // "frame 3: 1000448 pairs found, more than the pair budget of 1000000
    // (--max-pairs 1000000); ...".
    std::string pair_budget_refusal(uint64_t frame, uint64_t found) const;

private:
    void check_memory(uint64_t max_objects, uint64_t frames);
    void check_time(uint64_t max_objects, uint64_t frames) const;
    std::string objects_text(uint64_t max_objects) const;
    std::string frames_text(uint64_t frames) const;
    std::string pairs_origin() const;
    // A setting as the face names it, for advice: "--max-memory".
    std::string named(const char* setting) const;

    const SettingValues& values_;
    PlatformConfig platform_;
    BudgetShape shape_;
    FrameOrigin origin_;
    MachineMemory machine_;
    uint64_t memory_bytes_ = 0;
    std::string memory_origin_;
    Footprint footprint_;
    uint64_t pairs_ = PairBudget::kUnlimited;
};

}  // namespace cdvp
