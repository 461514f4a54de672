// The whole platform on either engine: the same scenes through the clocked
// and the fast board give identical pairs in identical order, identical
// cycles, stalls and pauses, and identical per-phase times (quantum 0), over
// buses, transfer and wait modes, parallelism, FIFO and pair-buffer depths,
// and a host polling at odd moments.
#include <gtest/gtest.h>

#include <algorithm>
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

struct Variant {
    const char* name;
    uint32_t m;
    uint32_t fifo_depth;  // 0: the preset's
    uint32_t buffer_depth;
    bool dma, irq;
    double poll_gap_ns;
    uint32_t tile_boxes = 0;  // 0: boxes in block RAM; else SSRAM tiles of this many boxes
    NumberFormat format = NumberFormat::float32();
    uint32_t grid_cell_capacity = 0;  // 0: the all-pairs board; else a grid board with cells this deep
};

PlatformConfig platform_for(const Variant& v, Fidelity fidelity) {
    PlatformConfig config = testing::preset_platform("adm-xrc-ii");
    config.board.m = v.m;
    config.board.format = v.format;
    if (v.fifo_depth != 0) config.board.collector.fifo_depth = v.fifo_depth;
    config.board.collector.buffer_depth = v.buffer_depth;
    config.driver.transfer = (v.dma) ? Transfer::kDma : Transfer::kPio;
    config.driver.wait = (v.irq) ? WaitMode::kIrq : WaitMode::kPoll;
    config.driver.poll_gap_ns = v.poll_gap_ns;
    config.board.tiles.boxes = v.tile_boxes;
    if (v.grid_cell_capacity != 0) {
        config.board.algorithm = BoardAlgorithm::kGrid;
        config.board.grid.cell_capacity = v.grid_cell_capacity;
    }
    config.fidelity = fidelity;
    return config;
}

void expect_same_frame(const FrameResult& cycle, const FrameResult& fast, const std::string& where) {
    ASSERT_EQ(fast.pairs, cycle.pairs) << where << ": the same pairs in the same order";
    const FramePhases& a = cycle.phases;
    const FramePhases& b = fast.phases;
    EXPECT_EQ(b.compute_cycles, a.compute_cycles) << where;
    EXPECT_EQ(b.stall_cycles, a.stall_cycles) << where;
    EXPECT_EQ(b.overflow_pauses, a.overflow_pauses) << where;
    for (const auto& [x, y, phase] : {std::tuple{a.upload_ns, b.upload_ns, "upload"},
                                      std::tuple{a.start_ns, b.start_ns, "start"},
                                      std::tuple{a.compute_ns, b.compute_ns, "compute"},
                                      std::tuple{a.irq_ns, b.irq_ns, "irq"},
                                      std::tuple{a.readback_ns, b.readback_ns, "readback"},
                                      std::tuple{a.driver_ns, b.driver_ns, "driver"},
                                      std::tuple{a.total_ns, b.total_ns, "total"}}) {
        EXPECT_EQ(y, x) << where << ": " << phase << " time";
    }
}

struct Totals {
    uint64_t pairs = 0, stalls = 0, pauses = 0;
};

// One platform pair per variant, elaborated before the first frame; the
// pairs of variant k in scene s into (*pairs)[k][s] when asked.
Totals expect_equivalent(const std::vector<Variant>& variants, uint32_t capacity,
                         const std::vector<std::vector<FloatBox>>& scenes,
                         std::vector<std::vector<PairList>>* pairs = nullptr) {
    Totals totals;
    std::vector<std::unique_ptr<VirtualBoard>> cycle, fast;
    for (const Variant& v : variants) {
        cycle.push_back(std::make_unique<VirtualBoard>((std::string(v.name) + "_cycle").c_str(),
                                                       platform_for(v, Fidelity::kCycle), capacity));
        fast.push_back(std::make_unique<VirtualBoard>((std::string(v.name) + "_fast").c_str(),
                                                      platform_for(v, Fidelity::kFast), capacity));
    }
    for (std::size_t k = 0; k < variants.size(); ++k) {
        for (std::size_t s = 0; s < scenes.size(); ++s) {
            const FrameResult a = cycle[k]->run_frame(scenes[s]);
            const FrameResult& b = fast[k]->run_frame(scenes[s]);
            expect_same_frame(a, b, std::string(variants[k].name) + ", scene " + std::to_string(s) + " (" +
                                        std::to_string(scenes[s].size()) + " boxes)");
            if (::testing::Test::HasFatalFailure()) return totals;
            if (pairs != nullptr) {
                pairs->resize(variants.size());
                (*pairs)[k].push_back(a.pairs);
            }
            totals.pairs += a.pairs.size();
            totals.stalls += a.phases.stall_cycles;
            totals.pauses += a.phases.overflow_pauses;
        }
    }
    return totals;
}

TEST(EngineEquivalence, ScenesOfEverySizeOverModesAndParallelism) {
    std::mt19937 rng(77);
    std::vector<std::vector<FloatBox>> scenes;
    for (uint32_t n : {0u, 1u, 2u, 37u, 511u, 512u, 513u, 600u}) {
        scenes.push_back(testing::random_boxes(n, 1.2f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng));
    }
    const Totals t = expect_equivalent({{"dma_irq_m8", 8, 0, 262144, true, true, 0},
                                        {"dma_poll_m3", 3, 5, 64, true, false, 37},
                                        {"pio_irq_m1", 1, 1, 100, false, true, 0},
                                        {"pio_poll_m32", 32, 63, 1000, false, false, 113}},
                                       600, scenes);
    EXPECT_GT(t.pairs, 4u * 1000u) << "scenes with pairs to find";
    EXPECT_GT(t.pauses, 10u) << "some overflow pauses";
    EXPECT_GT(t.stalls, 50u) << "some back-pressure and drain";
}

// Every box meets every other: the smallest FIFO holds the pipeline back and
// pair buffers of 1 to 7 pause the board hundreds of times a frame.
TEST(EngineEquivalence, AllOverlappingScenesWithTinyBuffers) {
    std::mt19937 rng(78);
    std::vector<std::vector<FloatBox>> scenes{std::vector<FloatBox>(45, FloatBox{{0, 0, 0}, {1, 1, 1}}),
                                              testing::random_boxes(60, 1.0f, 2.0f, rng)};
    std::vector<Variant> variants;
    static const char* names[] = {"b1", "b2", "b3", "b4", "b5", "b6", "b7"};
    for (uint32_t depth = 1; depth <= 7; ++depth) {
        const uint32_t m = 1 + depth % 4;
        variants.push_back({names[depth - 1], m, 2 * m - 1, depth, depth % 2 == 0, depth % 3 != 0, 17.0 * depth});
    }
    const Totals t = expect_equivalent(variants, 60, scenes);
    EXPECT_GT(t.pauses, 1000u) << "hundreds of overflow pauses a frame";
}

// Every class of number format through the whole platform: the driver reads
// FORMAT and quantises, both engines compare in the format; and no pair of
// the float32 board is missing from the fixed-point boards' pairs.
TEST(EngineEquivalence, EveryNumberFormatClassThroughThePlatform) {
    std::mt19937 rng(79);
    std::vector<std::vector<FloatBox>> scenes;
    for (uint32_t n : {0u, 1u, 40u, 700u}) {
        scenes.push_back(testing::random_boxes(n, 1.5f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng));
    }
    std::vector<Variant> variants;
    static const char* names[] = {"float32", "fixed8", "fixed9", "fixed16", "fixed18", "fixed24", "fixed31", "fixed32"};
    for (const char* name : names) {
        variants.push_back({name, 3, 5, 97, true, true, 0, 0, NumberFormat::parse(name)});
    }
    std::vector<std::vector<PairList>> pairs;
    expect_equivalent(variants, 700, scenes, &pairs);
    if (HasFatalFailure()) return;
    const auto before = [](const IndexPair& a, const IndexPair& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    };
    uint64_t extra = 0;
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const PairList& reference = pairs[0][s];  // float32
        for (std::size_t k = 1; k < variants.size(); ++k) {
            const PairList& found = pairs[k][s];
            EXPECT_TRUE(std::includes(found.begin(), found.end(), reference.begin(), reference.end(), before))
                << variants[k].name << ": a pair of the float32 board is missing (" << scenes[s].size() << " boxes)";
            extra += found.size() - reference.size();
        }
    }
    EXPECT_GT(extra, 0u) << "coarse formats add pairs";
}

// Boxes in SSRAM, swept in small tiles (partial last tiles, up to 20 tiles):
// loads, bubbles and pauses at tile borders through the whole platform.
TEST(EngineEquivalence, TiledBoardsOverModesTilesAndTinyBuffers) {
    std::mt19937 rng(79);
    std::vector<std::vector<FloatBox>> scenes;
    for (uint32_t n : {0u, 1u, 2u, 3u, 31u, 64u, 97u, 160u}) {
        scenes.push_back(testing::random_boxes(n, 0.8f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng));
    }
    scenes.push_back(std::vector<FloatBox>(50, FloatBox{{0, 0, 0}, {1, 1, 1}}));
    const Totals t = expect_equivalent({{"t1_dma_irq_m1", 1, 1, 3, true, true, 0, 1},
                                        {"t8_pio_poll_m3", 3, 5, 7, false, false, 29, 8},
                                        {"t13_dma_poll_m2", 2, 3, 2, true, false, 11, 13},
                                        {"t32_pio_irq_m8", 8, 15, 5, false, true, 0, 32},
                                        {"t64_dma_irq_m32", 32, 63, 1000, true, true, 0, 64},
                                        {"t16_fixed9_m4", 4, 7, 5, true, true, 0, 16, NumberFormat::fixed(9)},
                                        {"t40_fixed24_m2", 2, 3, 3, false, true, 0, 40, NumberFormat::fixed(24)}},
                                       160, scenes);
    EXPECT_GT(t.pairs, 2000u) << "scenes with pairs to find";
    EXPECT_GT(t.pauses, 500u) << "overflow pauses, some at tile borders";
    EXPECT_GT(t.stalls, 500u) << "back-pressure and drain";
}

// The grid board (docs/grid_board.md) through the whole platform: its
// binning passes, cell sweeps, large boxes (a slab through every scene, and
// cells of a few boxes overflowing) and pauses, over modes and formats; the
// driver opens it by its ID and times out by its worst case.
TEST(EngineEquivalence, GridBoardsOverModesFormatsAndTinyBuffers) {
    std::mt19937 rng(80);
    std::vector<std::vector<FloatBox>> scenes;
    for (uint32_t n : {0u, 1u, 2u, 3u, 60u, 400u, 900u}) {
        std::vector<FloatBox> boxes = testing::random_boxes(n, 1.5f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng);
        if (n > 50) boxes.push_back(FloatBox{{-1e3f, -1e3f, 0.0f}, {1e3f, 1e3f, 0.5f}});
        scenes.push_back(std::move(boxes));
    }
    scenes.push_back(std::vector<FloatBox>(50, FloatBox{{0, 0, 0}, {1, 1, 1}}));
    const Totals t = expect_equivalent({{"g_dma_irq_m8", 8, 0, 262144, true, true, 0, 0, NumberFormat::float32(), 512},
                                        {"g_pio_poll_m3", 3, 5, 7, false, false, 29, 0, NumberFormat::float32(), 6},
                                        {"g_dma_poll_m1", 1, 1, 2, true, false, 11, 0, NumberFormat::float32(), 16},
                                        {"g_fixed9_m4", 4, 7, 5, true, true, 0, 0, NumberFormat::fixed(9), 8},
                                        {"g_fixed24_m2", 2, 3, 3, false, true, 0, 0, NumberFormat::fixed(24), 40}},
                                       901, scenes);
    EXPECT_GT(t.pairs, 2000u) << "scenes with pairs to find";
    EXPECT_GT(t.pauses, 500u) << "overflow pauses";
    EXPECT_GT(t.stalls, 500u) << "back-pressure and drain";
}

}  // namespace
}  // namespace cdvp
