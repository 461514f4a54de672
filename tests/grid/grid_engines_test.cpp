// The grid board's fast engine held to its clocked engine query by query:
// every segment's end, the counters at random edges, the pair buffer at each
// pause and at done, abort at any edge, and the grid registers.
#include <gtest/gtest.h>

#include <random>

#include "models/grid_clocked_engine/grid_clocked_engine.h"
#include "models/grid_fast_engine/grid_fast_board_engine.h"
#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

struct Shape {
    uint32_t m, fifo, drain, buffer;
    uint32_t latency, cycles_per_box;
    uint32_t dims, capacity, span;
};

BoardConfig board_of(const Shape& s, NumberFormat format = NumberFormat::float32()) {
    BoardConfig config;
    config.algorithm = BoardAlgorithm::kGrid;
    config.format = format;
    config.m = s.m;
    config.collector.fifo_depth = s.fifo;
    config.collector.drain_per_cycle = s.drain;
    config.collector.buffer_depth = s.buffer;
    config.tiles.load_latency_cycles = s.latency;
    config.tiles.cycles_per_box = s.cycles_per_box;
    config.grid.dims = s.dims;
    config.grid.cell_capacity = s.capacity;
    config.grid.max_span = s.span;
    return config;
}

// Small FIFOs and buffers (back-pressure, pauses), slow and fast SSRAM,
// fitted and fixed grids, small cells (overflow) and narrow spans (large boxes).
const Shape kShapes[] = {
    {3, 5, 1, 7, 2, 1, 0, 512, 8},      {8, 15, 1, 262144, 2, 1, 0, 512, 8}, {2, 3, 2, 40, 0, 6, 4, 9, 2},
    {5, 200, 4, 1, 8, 2, 0, 16, 1},     {1, 1, 1, 13, 3, 3, 11, 3, 64},
};

void expect_same(const BoardConfig& config, const testing::WordScene& scene, std::mt19937& rng) {
    GridClockedEngine clocked(config, scene.size());
    GridFastBoardEngine fast(config);
    testing::expect_same_engines(clocked, fast, scene, rng);
    EXPECT_EQ(clocked.grid_stats(), fast.grid_stats()) << "the grid registers";
}

TEST(GridEngines, TheFastEngineAnswersAsTheClockedOne) {
    std::mt19937 rng(31);
    for (uint32_t n : {0u, 1u, 2u, 3u, 90u, 700u}) {
        const auto scene = testing::random_scene(n, 2.2f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng);
        for (const Shape& shape : kShapes) {
            expect_same(board_of(shape), scene, rng);
            if (HasFailure()) return;
        }
    }
}

TEST(GridEngines, DenseAndSpanningScenesThroughTheLargeSweep) {
    std::mt19937 rng(32);
    for (const Shape& shape : kShapes) {
        expect_same(board_of(shape), testing::overlapping_scene(160, rng), rng);
        auto scene = testing::random_scene(400, 12.0f, 2.0f, rng);
        const float slab[6] = {-1e3f, -1e3f, 0.0f, 1e3f, 1e3f, 0.5f};
        for (uint32_t c = 0; c < kCoordinates; ++c) scene.words[c].insert(scene.words[c].begin() + 17, ComparisonUnit::as_bits(slab[c]));
        expect_same(board_of(shape), scene, rng);
        if (HasFailure()) return;
    }
}

TEST(GridEngines, SpecialValuesAndFixedPointFormats) {
    std::mt19937 rng(33);
    for (const Shape& shape : kShapes) {
        auto scene = testing::random_scene(300, 9.0f, 2.0f, rng);
        testing::sprinkle_special_values(scene, 0.05, rng);
        expect_same(board_of(shape), scene, rng);
        for (uint32_t k : {8u, 16u, 32u}) {
            const NumberFormat format = NumberFormat::fixed(k);
            expect_same(board_of(shape, format), testing::fixed_scene(300, format, 0.05, rng), rng);
        }
        if (HasFailure()) return;
    }
}

// ABORT at any edge: the buffer keeps what it held then, in both.
TEST(GridEngines, AbortKeepsTheBufferOfThatEdge) {
    std::mt19937 rng(34);
    const auto scene = testing::random_scene(300, 8.0f, 2.0f, rng);
    const BoardConfig config = board_of(kShapes[0]);
    testing::expect_same_aborts([&] { return std::make_unique<GridClockedEngine>(config, scene.size()); },
                                [&] { return std::make_unique<GridFastBoardEngine>(config); }, scene, rng);
}

// Every edge of a sweep, probed: the clocked engine walks the passes in the
// closed form's slots (its cycles are the slots, L and the stalls).
TEST(GridEngines, EveryEdgeOfASmallSweep) {
    std::mt19937 rng(35);
    const auto scene = testing::random_scene(60, 5.0f, 2.0f, rng);
    for (const Shape& shape : kShapes) {
        GridClockedEngine clocked(board_of(shape), scene.size());
        GridFastBoardEngine fast(board_of(shape));
        testing::expect_same_engines(clocked, fast, scene, rng, 2000);
        const SweepCounters end = clocked.counters_after(UINT64_MAX);
        EXPECT_EQ(clocked.grid_stats().slots + board_of(shape).pipeline_latency() + end.stalls, end.cycles);
    }
}

}  // namespace
}  // namespace cdvp
