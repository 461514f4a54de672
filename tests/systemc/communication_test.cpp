// The communication strategies through the whole platform (driver, bus,
// bridge, board) on both engines: every upload mode, pair format, interrupt
// policy and poll back-off finds the same pairs as the paper's driver, the
// clocked and fast boards agree on every time, a delta upload sends exactly
// the boxes that moved, and after a fault the next frame uploads them all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "models/common/fault_plan.h"
#include "platform/analytic_platform.h"
#include "platform/virtual_board.h"
#include "tests/support/core_driver.h"
#include "tests/support/preset_platform.h"

namespace cdvp {
namespace {

using testing::moving_frames;
constexpr auto changed = testing::changed_boxes;

struct Strategy {
    const char* name;
    UploadMode upload;
    PairFormat format;
    InterruptPolicy interrupts;
    WaitMode wait = WaitMode::kIrq;
    Transfer transfer = Transfer::kDma;
    double backoff = 1.0;
    uint32_t tile_boxes = 0;
};

PlatformConfig platform_for(const Strategy& s, Fidelity fidelity) {
    PlatformConfig config = testing::preset_platform("adm-xrc-ii");
    config.board.m = 4;
    config.board.collector.buffer_depth = 50;  // pauses in every frame
    config.board.tiles.boxes = s.tile_boxes;
    config.driver.upload = s.upload;
    config.driver.pair_format = s.format;
    config.driver.interrupts = s.interrupts;
    config.driver.wait = s.wait;
    config.driver.transfer = s.transfer;
    config.driver.poll_backoff = s.backoff;
    config.driver.poll_gap_ns = 200;
    config.driver.poll_gap_max_ns = 5000;
    config.fidelity = fidelity;
    return config;
}

TEST(Communication, EveryStrategyFindsThePairsAndBothEnginesAgree) {
    const std::vector<Strategy> strategies = {
        {"paper", UploadMode::kFull, PairFormat::kList, InterruptPolicy::kEvery},
        {"delta_counted", UploadMode::kDelta, PairFormat::kCounted, InterruptPolicy::kEvery},
        {"auto_bitmap_board", UploadMode::kAuto, PairFormat::kBitmap, InterruptPolicy::kBoard},
        {"delta_list_board", UploadMode::kDelta, PairFormat::kList, InterruptPolicy::kBoard},
        {"delta_pio_poll", UploadMode::kDelta, PairFormat::kCounted, InterruptPolicy::kEvery, WaitMode::kPoll,
         Transfer::kPio, 2.0},
        {"delta_bitmap_poll_tiles", UploadMode::kDelta, PairFormat::kBitmap, InterruptPolicy::kEvery, WaitMode::kPoll,
         Transfer::kDma, 1.5, 64},
    };
    std::mt19937 rng(91);
    const auto frames = moving_frames(300, rng);
    std::vector<std::unique_ptr<VirtualBoard>> cycle, fast;
    for (const Strategy& s : strategies) {
        cycle.push_back(std::make_unique<VirtualBoard>((std::string(s.name) + "_cycle").c_str(),
                                                       platform_for(s, Fidelity::kCycle), 301));
        fast.push_back(std::make_unique<VirtualBoard>((std::string(s.name) + "_fast").c_str(),
                                                      platform_for(s, Fidelity::kFast), 301));
    }
    std::vector<PairList> reference;
    std::vector<double> paper_total;
    for (std::size_t k = 0; k < strategies.size(); ++k) {
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const std::string where = std::string(strategies[k].name) + ", frame " + std::to_string(f);
            const FrameResult a = cycle[k]->run_frame(frames[f]);
            const FrameResult& b = fast[k]->run_frame(frames[f]);
            ASSERT_EQ(a.pairs, b.pairs) << where;
            EXPECT_EQ(a.phases.total_ns, b.phases.total_ns) << where;
            EXPECT_EQ(a.phases.upload_ns, b.phases.upload_ns) << where;
            EXPECT_EQ(a.phases.readback_ns, b.phases.readback_ns) << where;
            EXPECT_EQ(a.phases.upload_bytes, b.phases.upload_bytes) << where;
            EXPECT_EQ(a.phases.readback_bytes, b.phases.readback_bytes) << where;
            EXPECT_GT(a.phases.overflow_pauses, 0u) << where;
            if (k == 0) {
                reference.push_back(sorted(a.pairs));
                paper_total.push_back(a.phases.total_ns);
                EXPECT_EQ(a.phases.boxes_sent, frames[f].size());
                EXPECT_EQ(a.phases.readback_bytes, 8 * a.pairs.size()) << where;
            } else {
                EXPECT_EQ(reference[f], sorted(a.pairs)) << where;
            }
            if (strategies[k].upload == UploadMode::kDelta) {
                const uint32_t moved = f == 0 ? frames[0].size() : changed(frames[f - 1], frames[f]);
                EXPECT_EQ(moved, a.phases.boxes_sent) << where;
                EXPECT_EQ(28u * moved, a.phases.upload_bytes) << where;
            }
            if (strategies[k].upload == UploadMode::kAuto && f > 0) {
                EXPECT_LT(a.phases.boxes_sent, frames[f].size()) << where << ": a fifth moved, the delta is cheaper";
            }
        }
    }
    EXPECT_GT(reference[1].size(), 200u) << "frames with pairs to find";
}

// A fault leaves what the board's memories hold unknown: the next frame
// sends every box, and the frame after it only the moved ones again.
TEST(Communication, AfterAFaultTheNextFrameUploadsEveryBox) {
    std::mt19937 rng(92);
    const auto frames = moving_frames(200, rng);
    PlatformConfig config = platform_for({"delta", UploadMode::kDelta, PairFormat::kList, InterruptPolicy::kEvery},
                                         Fidelity::kFast);
    config.faults = {FaultSpec{FaultKind::kBoardError, 2}};
    VirtualBoard board("board", config, 201);
    // Elaborated before the first frame, as every module must be.
    PlatformConfig clean = platform_for({"full", UploadMode::kFull, PairFormat::kList, InterruptPolicy::kEvery},
                                        Fidelity::kFast);
    VirtualBoard reference("reference", clean, 201);
    EXPECT_EQ(200u, board.run_frame(frames[0], 0).phases.boxes_sent);
    EXPECT_EQ(40u, board.run_frame(frames[1], 1).phases.boxes_sent);
    FrameFault fault;
    EXPECT_EQ(nullptr, board.try_run_frame(frames[2], 2, fault)) << "the injected board error fails frame 2";
    const FrameResult& after = board.run_frame(frames[3], 3);
    EXPECT_EQ(frames[3].size(), after.phases.boxes_sent);
    EXPECT_EQ(sorted(reference.run_frame(frames[3], 3).pairs), sorted(after.pairs));
    EXPECT_EQ(changed(frames[3], frames[4]), board.run_frame(frames[4], 4).phases.boxes_sent);
}

// The analytic level times every strategy as the platform does: where the
// board does not stall, every phase is exact (polling through pauses aside,
// whose notices depend on segment lengths it spreads evenly), and the
// pairs, boxes sent and bytes moved are the platform's.
TEST(Communication, TheAnalyticLevelTimesEveryStrategyPhaseByPhase) {
    const std::vector<Strategy> strategies = {
        {"paper", UploadMode::kFull, PairFormat::kList, InterruptPolicy::kEvery},
        {"delta_counted", UploadMode::kDelta, PairFormat::kCounted, InterruptPolicy::kEvery},
        {"auto_bitmap_board", UploadMode::kAuto, PairFormat::kBitmap, InterruptPolicy::kBoard},
        {"delta_list_board_poll", UploadMode::kDelta, PairFormat::kList, InterruptPolicy::kBoard, WaitMode::kPoll,
         Transfer::kDma, 1.0},
        {"delta_pio_backoff", UploadMode::kDelta, PairFormat::kCounted, InterruptPolicy::kEvery, WaitMode::kPoll,
         Transfer::kPio, 2.0},
        {"auto_bitmap_backoff_tiles", UploadMode::kAuto, PairFormat::kBitmap, InterruptPolicy::kBoard, WaitMode::kPoll,
         Transfer::kDma, 1.5, 64},
    };
    std::vector<std::unique_ptr<VirtualBoard>> platforms;
    for (const Strategy& s : strategies) {
        platforms.push_back(std::make_unique<VirtualBoard>((std::string(s.name) + "_platform").c_str(),
                                                           platform_for(s, Fidelity::kFast), 301));
    }
    std::mt19937 rng(93);
    const auto frames = moving_frames(300, rng, 16.0f);
    int paused = 0;
    for (std::size_t k = 0; k < strategies.size(); ++k) {
        AnalyticPlatform analytic(platform_for(strategies[k], Fidelity::kFast), 301);
        for (std::size_t f = 0; f < frames.size(); ++f) {
            const std::string where = std::string(strategies[k].name) + ", frame " + std::to_string(f);
            const FrameResult& exact = platforms[k]->run_frame(frames[f]);
            FrameFault fault;
            const FrameResult* estimated = analytic.try_run_frame(frames[f], f, fault);
            ASSERT_NE(estimated, nullptr) << where;
            ASSERT_EQ(exact.phases.stall_cycles, exact.phases.overflow_pauses) << where << ": no FIFO stalls";
            EXPECT_EQ(estimated->pairs, exact.pairs) << where;
            const FramePhases& a = estimated->phases;
            const FramePhases& b = exact.phases;
            EXPECT_EQ(a.boxes_sent, b.boxes_sent) << where;
            EXPECT_EQ(a.upload_bytes, b.upload_bytes) << where;
            EXPECT_EQ(a.readback_bytes, b.readback_bytes) << where;
            const bool notices_exact = strategies[k].wait == WaitMode::kIrq || b.overflow_pauses == 0;
            for (const auto& [x, y, phase, claimed] :
                 {std::tuple{a.upload_ns, b.upload_ns, "upload", true}, std::tuple{a.start_ns, b.start_ns, "start", true},
                  std::tuple{a.compute_ns, b.compute_ns, "compute", true},
                  std::tuple{a.irq_ns, b.irq_ns, "irq", notices_exact},
                  std::tuple{a.readback_ns, b.readback_ns, "readback", true},
                  std::tuple{a.driver_ns, b.driver_ns, "driver", true},
                  std::tuple{a.total_ns, b.total_ns, "total", notices_exact}}) {
                if (claimed) {
                    EXPECT_NEAR(x, y, 1e-6 * std::max(1.0, y)) << where << ": " << phase;
                }
            }
            paused += b.overflow_pauses > 0;
        }
    }
    EXPECT_GT(paused, 5) << "frames that pause, so the read-back of every segment is checked";
}

}  // namespace
}  // namespace cdvp
