// The bound cdvp run estimates a frame's simulated time with, before any
// work, against what frames take through the whole platform: the bound must
// hold for every way of moving data and waiting, with overflow pauses, on the
// clocked and the fast engine, and under a loose host quantum.
#include "platform/driver/frame_time.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "platform/settings/board_preset.h"
#include "tests/support/preset_platform.h"
#include "platform/virtual_board.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

struct FrameVariant {
    const char* name;
    bool dma, interrupts;
    Fidelity fidelity;
    double quantum_ns;
};

PlatformConfig platform_config(const FrameVariant& v) {
    PlatformConfig config = testing::preset_platform("adm-xrc-ii");
    config.board.collector.buffer_depth = 64;  // pauses every 64 pairs
    config.driver.transfer = (v.dma) ? Transfer::kDma : Transfer::kPio;
    config.driver.wait = (v.interrupts) ? WaitMode::kIrq : WaitMode::kPoll;
    config.fidelity = v.fidelity;
    config.quantum_ns = v.quantum_ns;
    return config;
}

TEST(FrameTime, BoundsWhatEveryFrameTakesThroughThePlatform) {
    const FrameVariant variants[] = {{"dma_irq", true, true, Fidelity::kCycle, 0},
                                {"pio_poll", false, false, Fidelity::kCycle, 0},
                                {"dma_poll_fast", true, false, Fidelity::kFast, 0},
                                {"pio_irq_quantum", false, true, Fidelity::kFast, 10000}};
    std::vector<std::unique_ptr<VirtualBoard>> platforms;
    for (const FrameVariant& v : variants) {
        platforms.push_back(std::make_unique<VirtualBoard>(v.name, platform_config(v), 400));
    }
    std::mt19937 rng(12);
    for (uint32_t n : {0u, 1u, 40u, 400u}) {
        const std::vector<FloatBox> boxes = testing::random_boxes(n, 14.0f, 3.0f, rng);
        for (std::size_t k = 0; k < platforms.size(); ++k) {
            const PlatformConfig config = platform_config(variants[k]);
            const FrameResult& result = platforms[k]->run_frame(boxes);
            const FrameTime time(config.driver, platforms[k]->bus_timing(), platforms[k]->board().period().value(),
                                 config.board.m, config.board.collector.buffer_depth, config.board.tiles,
                                 config.quantum_ns);
            const double bound = time.frame_bound_ns(n, result.pairs.size());
            EXPECT_LE(result.phases.total_ns, bound) << variants[k].name << " n=" << n;
            EXPECT_LE(bound, 3 * result.phases.total_ns + 1e6) << variants[k].name << " n=" << n << ": not absurd";
            if (n == 400) {
                EXPECT_GT(result.phases.overflow_pauses, 2u) << variants[k].name;
            }
        }
    }
}

// A grid board's frames, spread and all in one cell (its cells overflow
// into the large sweep), stay within the bound taken from its registers.
TEST(FrameTime, BoundsWhatGridFramesTakeThroughThePlatform) {
    const FrameVariant variants[] = {{"grid_dma_irq", true, true, Fidelity::kCycle, 0},
                                {"grid_pio_poll_fast", false, false, Fidelity::kFast, 0}};
    std::vector<std::unique_ptr<VirtualBoard>> platforms;
    std::vector<PlatformConfig> configs;
    for (const FrameVariant& v : variants) {
        PlatformConfig config = platform_config(v);
        config.board.algorithm = BoardAlgorithm::kGrid;
        config.board.grid.cell_capacity = 16;
        configs.push_back(config);
        platforms.push_back(std::make_unique<VirtualBoard>(v.name, config, 400));
    }
    std::mt19937 rng(13);
    const std::vector<std::vector<FloatBox>> scenes{testing::random_boxes(400, 14.0f, 3.0f, rng),
                                                    std::vector<FloatBox>(120, FloatBox{{0, 0, 0}, {1, 1, 1}})};
    for (const std::vector<FloatBox>& boxes : scenes) {
        for (std::size_t k = 0; k < platforms.size(); ++k) {
            const FrameResult& result = platforms[k]->run_frame(boxes);
            FrameTime time(configs[k].driver, platforms[k]->bus_timing(), platforms[k]->board().period().value(),
                           configs[k].board.m, configs[k].board.collector.buffer_depth, configs[k].board.tiles,
                           configs[k].quantum_ns);
            time.set_grid(configs[k].board.grid);
            const auto n = static_cast<uint32_t>(boxes.size());
            EXPECT_LE(result.phases.total_ns, time.frame_bound_ns(n, result.pairs.size())) << variants[k].name << " n=" << n;
            EXPECT_GT(result.phases.overflow_pauses, 2u) << variants[k].name << " n=" << n;
        }
    }
}

TEST(FrameTime, QuotesSecondsToTheMillisecond) {
    EXPECT_EQ(simulated_seconds(ns_from_fs(kSimulatedTimeLimit)), "9223.372 s");
    EXPECT_EQ(simulated_seconds(1.5e6), "0.002 s");
}

}  // namespace
}  // namespace cdvp
