// Frames pipelined through the whole platform (driver, bus, bridge, board
// with two box banks) on both engines: the same pairs, cycles and pauses as
// one frame at a time, for every way of moving and waiting; the clocked and
// fast boards agree on every time; the frames' totals add up to less time
// than one at a time when the sweeps can hide behind the host's work, and a
// frame's latency spans its successor's upload. Deltas compare with the
// bank's own last frame, two frames back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "models/common/fault_plan.h"
#include "platform/virtual_board.h"
#include "tests/support/core_driver.h"
#include "tests/support/preset_platform.h"

namespace cdvp {
namespace {

// A different fifth of the boxes moves each frame, over six frames.
std::vector<std::vector<FloatBox>> jittered_frames(uint32_t n, std::mt19937& rng) {
    return testing::moving_frames(n, rng, 9.0f, 6, true);
}
constexpr auto changed_boxes_of = testing::changed_boxes;

struct PipelinedStrategy {
    const char* name;
    UploadMode upload = UploadMode::kFull;
    PairFormat format = PairFormat::kList;
    InterruptPolicy interrupts = InterruptPolicy::kEvery;
    WaitMode wait = WaitMode::kIrq;
    Transfer transfer = Transfer::kDma;
    uint32_t buffer_depth = 50;  // pauses in every frame
};

PlatformConfig platform_for(const PipelinedStrategy& s, Fidelity fidelity, uint32_t banks) {
    PlatformConfig config = testing::preset_platform("adm-xrc-ii");
    config.board.m = 2;
    config.board.box_banks = banks;
    config.board.collector.buffer_depth = s.buffer_depth;
    config.driver.upload = s.upload;
    config.driver.pair_format = s.format;
    config.driver.interrupts = s.interrupts;
    config.driver.wait = s.wait;
    config.driver.transfer = s.transfer;
    config.driver.poll_gap_ns = 200;
    config.fidelity = fidelity;
    return config;
}

// Every frame through a pipelined board: results in frame order.
std::vector<FrameResult> pipelined(VirtualBoard& board, const std::vector<std::vector<FloatBox>>& frames) {
    std::vector<FrameResult> results;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        FrameFault fault;
        const FrameResult* result = board.try_submit_frame(frames[f], f, fault);
        EXPECT_FALSE(fault) << fault.message;
        EXPECT_EQ(f == 0, result == nullptr) << "frame " << f << ": the frame before comes back";
        if (result != nullptr) results.push_back(*result);
    }
    FrameFault fault;
    const FrameResult* last = board.try_finish_frames(fault);
    EXPECT_FALSE(fault) << fault.message;
    EXPECT_NE(nullptr, last);
    if (last != nullptr) results.push_back(*last);
    EXPECT_EQ(nullptr, board.try_finish_frames(fault)) << "nothing left in flight";
    return results;
}

double phase_sum(const FramePhases& p) {
    return p.upload_ns + p.start_ns + p.compute_ns + p.irq_ns + p.readback_ns + p.driver_ns;
}

TEST(PipelinedFrames, FindThePairsOfOneFrameAtATimeAndBothEnginesAgree) {
    const std::vector<PipelinedStrategy> strategies = {
        {"paper"},
        {"delta_counted", UploadMode::kDelta, PairFormat::kCounted},
        {"bitmap_board", UploadMode::kFull, PairFormat::kBitmap, InterruptPolicy::kBoard},
        {"delta_poll", UploadMode::kDelta, PairFormat::kList, InterruptPolicy::kEvery, WaitMode::kPoll},
        {"pio_deep_buffer", UploadMode::kFull, PairFormat::kList, InterruptPolicy::kEvery, WaitMode::kIrq,
         Transfer::kPio, 100000},
    };
    std::mt19937 rng(41);
    const auto frames = jittered_frames(240, rng);
    std::vector<std::unique_ptr<VirtualBoard>> cycle, fast, single;
    for (const PipelinedStrategy& s : strategies) {
        const std::string name = s.name;
        cycle.push_back(std::make_unique<VirtualBoard>((name + "_cycle").c_str(), platform_for(s, Fidelity::kCycle, 2), 241));
        fast.push_back(std::make_unique<VirtualBoard>((name + "_fast").c_str(), platform_for(s, Fidelity::kFast, 2), 241));
        single.push_back(std::make_unique<VirtualBoard>((name + "_single").c_str(), platform_for(s, Fidelity::kFast, 1), 241));
    }
    for (std::size_t k = 0; k < strategies.size(); ++k) {
        ASSERT_TRUE(cycle[k]->pipelined());
        ASSERT_FALSE(single[k]->pipelined());
        const std::vector<FrameResult> a = pipelined(*cycle[k], frames);
        const std::vector<FrameResult> b = pipelined(*fast[k], frames);
        ASSERT_EQ(frames.size(), a.size());
        ASSERT_EQ(frames.size(), b.size());
        double pipelined_total = 0, single_total = 0;
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const std::string where = std::string(strategies[k].name) + ", frame " + std::to_string(f);
            const FrameResult one = single[k]->run_frame(frames[f], f);
            ASSERT_EQ(one.pairs, a[f].pairs) << where << ": the same pairs in the board's order";
            ASSERT_EQ(a[f].pairs, b[f].pairs) << where;
            EXPECT_EQ(one.phases.compute_cycles, a[f].phases.compute_cycles) << where;
            EXPECT_EQ(one.phases.stall_cycles, a[f].phases.stall_cycles) << where;
            EXPECT_EQ(one.phases.overflow_pauses, a[f].phases.overflow_pauses) << where;
            EXPECT_EQ(one.phases.readback_bytes, a[f].phases.readback_bytes) << where;
            EXPECT_EQ(a[f].phases.total_ns, b[f].phases.total_ns) << where << ": clocked and fast";
            EXPECT_EQ(a[f].phases.latency_ns, b[f].phases.latency_ns) << where;
            EXPECT_EQ(a[f].phases.overlap_ns, b[f].phases.overlap_ns) << where;
            EXPECT_NEAR(phase_sum(a[f].phases), a[f].phases.total_ns, 1e-6 * a[f].phases.total_ns) << where;
            EXPECT_GE(a[f].phases.latency_ns, a[f].phases.total_ns) << where;
            EXPECT_NEAR(one.phases.compute_ns, a[f].phases.compute_ns + a[f].phases.overlap_ns, 1e-6) << where
                << ": the sweep is waited for or hidden";
            if (strategies[k].upload == UploadMode::kDelta) {
                // Each bank keeps its own last frame: two frames back.
                const uint32_t moved = f < 2 ? frames[f].size() : changed_boxes_of(frames[f - 2], frames[f]);
                EXPECT_EQ(moved, a[f].phases.boxes_sent) << where;
            } else {
                EXPECT_EQ(frames[f].size(), a[f].phases.boxes_sent) << where;
            }
            pipelined_total += a[f].phases.total_ns;
            single_total += one.phases.total_ns;
        }
        // A delta is taken against the bank's own last frame, two frames
        // back: more boxes moved, which may cost more than the sweep hides.
        if (strategies[k].upload == UploadMode::kFull) {
            EXPECT_LT(pipelined_total, single_total) << strategies[k].name << ": sweeps hide behind uploads";
        }
        for (const FrameResult& r : a) EXPECT_EQ(0u, r.phases.timeouts_recovered) << strategies[k].name;
    }
}

// Without pair-buffer pauses, a frame's sweep runs beside the next frame's
// upload: its compute is hidden (overlap), and its latency is more than
// the host's time on it.
TEST(PipelinedFrames, ASweepHidesBehindTheNextUploadAndLatencyGrows) {
    std::mt19937 rng(42);
    const auto frames = jittered_frames(400, rng);
    const PipelinedStrategy paper{"paper", UploadMode::kFull, PairFormat::kList, InterruptPolicy::kEvery, WaitMode::kIrq,
                         Transfer::kDma, 100000};
    VirtualBoard two("two", platform_for(paper, Fidelity::kFast, 2), 401);
    VirtualBoard one("one", platform_for(paper, Fidelity::kFast, 1), 401);
    const std::vector<FrameResult> results = pipelined(two, frames);
    ASSERT_EQ(frames.size(), results.size());
    for (std::size_t f = 0; f + 1 < frames.size(); ++f) {
        const FrameResult single = one.run_frame(frames[f], f);
        const FramePhases& p = results[f].phases;
        EXPECT_GT(p.overlap_ns, 0.0) << "frame " << f;
        EXPECT_LT(p.total_ns, single.phases.total_ns) << "frame " << f;
        EXPECT_GT(p.latency_ns, p.total_ns) << "frame " << f;
    }
    EXPECT_EQ(0.0, one.run_frame(frames.back(), 9).phases.overlap_ns) << "one frame at a time hides nothing";
}

// On an ideal bus no time passes between two status reads: an interrupt
// already seen must not end the wait for the next one (each is taken once).
TEST(PipelinedFrames, AnIdealBusPipelinesToo) {
    std::mt19937 rng(44);
    const auto frames = jittered_frames(60, rng);
    BoardConfig two;
    two.box_banks = 2;
    BoardConfig one = two;
    one.box_banks = 1;
    VirtualBoard pipelined_board("two", two, 61);
    VirtualBoard single("one", one, 61);
    const std::vector<FrameResult> results = pipelined(pipelined_board, frames);
    ASSERT_EQ(frames.size(), results.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const FrameResult reference = single.run_frame(frames[f], f);
        EXPECT_EQ(reference.pairs, results[f].pairs) << "frame " << f;
        EXPECT_EQ(reference.phases.compute_cycles, results[f].phases.compute_cycles) << "frame " << f;
    }
}

// A fault ends both frames in flight; the next submission starts afresh
// (nothing comes back) and uploads every box, as after any fault.
TEST(PipelinedFrames, AFaultEndsTheFramesInFlightAndTheNextStartsAfresh) {
    std::mt19937 rng(43);
    const auto frames = jittered_frames(200, rng);
    PlatformConfig config = platform_for({"delta", UploadMode::kDelta}, Fidelity::kFast, 2);
    config.faults = {FaultSpec{FaultKind::kBoardError, 2}};
    VirtualBoard board("board", config, 201);
    FrameFault fault;
    EXPECT_EQ(nullptr, board.try_submit_frame(frames[0], 0, fault));
    EXPECT_FALSE(fault);
    ASSERT_NE(nullptr, board.try_submit_frame(frames[1], 1, fault));
    EXPECT_EQ(nullptr, board.try_submit_frame(frames[2], 2, fault));
    EXPECT_TRUE(fault) << "the injected board error";
    EXPECT_EQ(nullptr, board.try_finish_frames(fault));
    EXPECT_FALSE(fault) << "nothing in flight after a fault";
    EXPECT_EQ(nullptr, board.try_submit_frame(frames[3], 3, fault));
    EXPECT_FALSE(fault) << fault.message;
    const FrameResult* after = board.try_submit_frame(frames[4], 4, fault);
    ASSERT_NE(nullptr, after) << fault.message;
    EXPECT_EQ(frames[3].size(), after->phases.boxes_sent) << "after a fault every box is sent";
}

}  // namespace
}  // namespace cdvp
