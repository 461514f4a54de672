// Both engines in every class of number format: float32, fixed widths at the
// block RAM aspect boundaries (8/9, 16/18), 24, 31 and the full 32 bits.
// Pairs, their order, cycles, stalls and counters must agree edge for edge.
#include <gtest/gtest.h>

#include <random>

#include "models/fast_engine/fast_engine.h"
#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

using testing::expect_lockstep;
using testing::WordScene;

std::vector<NumberFormat> format_classes() {
    std::vector<NumberFormat> formats{NumberFormat::float32()};
    for (uint32_t k : {8u, 9u, 16u, 18u, 24u, 31u, 32u}) formats.push_back(NumberFormat::fixed(k));
    return formats;
}

BoardConfig make_config(NumberFormat format, uint32_t m, uint32_t fifo, uint32_t drain, uint32_t buffer) {
    BoardConfig config = testing::collector_config(m, fifo, drain, buffer);
    config.format = format;
    return config;
}

// Scenes that mean something in the format, and float scenes read as its words
// (any word is legal input: the memories keep the low K bits).
std::vector<WordScene> scenes_for(NumberFormat format, uint32_t n, std::mt19937& rng) {
    std::vector<WordScene> scenes;
    scenes.push_back(testing::fixed_scene(n, format, 0.3, rng));
    scenes.push_back(testing::random_scene(n, 4.0f, 2.0f, rng));
    WordScene special = testing::random_scene(n, 6.0f, 2.0f, rng);
    testing::sprinkle_special_values(special, 0.05, rng);
    scenes.push_back(special);
    return scenes;
}

TEST(FormatEquivalence, EveryEdgeOfSmallScenesInEveryFormat) {
    std::mt19937 rng(91);
    uint32_t pauses = 0;
    for (NumberFormat format : format_classes()) {
        for (uint32_t m : {1u, 3u, 6u}) {
            for (uint32_t n : {0u, 1u, 2u, 17u, 40u}) {
                for (const WordScene& scene : scenes_for(format, n, rng)) {
                    const BoardConfig config = make_config(format, m, 2 * m - 1, 1 + n % 3, 1 + n % 7);
                    pauses += expect_lockstep(config, scene, 0, rng) - 1;
                    if (HasFailure()) return;
                }
            }
        }
    }
    EXPECT_GT(pauses, 150u);
}

// Past the primitives' depth in each format's layout (512, or 1,024 for
// the narrowest words), so the cascades are read across their borders.
TEST(FormatEquivalence, AcrossBlockRamAspectsWithBackPressure) {
    std::mt19937 rng(92);
    for (NumberFormat format : format_classes()) {
        const uint32_t boxes = format.bits() <= 9 ? 2051 : 515;
        ASSERT_LT(format.block_ram_layout(boxes).depth, boxes) << format.name();
        const WordScene scene = testing::fixed_scene(boxes, format, 0.01, rng);
        expect_lockstep(make_config(format, 4, 7, 1, 9), scene, 30, rng);
        expect_lockstep(make_config(format, 24, 47, 2, 262144), scene, 30, rng);
        if (HasFailure()) return;
    }
}

// Boxes in SSRAM swept in tiles: the tile buffers in the format's aspect,
// the pairs in the tiled schedule's order, in every format.
TEST(FormatEquivalence, TiledBoardsInEveryFormat) {
    std::mt19937 rng(94);
    for (NumberFormat format : format_classes()) {
        for (uint32_t tile : {7u, 64u}) {
            BoardConfig config = make_config(format, 3, 5, 1 + tile % 3, 11);
            config.tiles.boxes = tile;
            expect_lockstep(config, testing::fixed_scene(150, format, 0.2, rng), 40, rng);
            if (HasFailure()) return;
        }
    }
}

// The pair finder's both algorithms (all pairs; grid sweep with and without
// grouping by cell) against the lane test of the format.
TEST(FormatEquivalence, PairFinderEqualsTheLaneTestOfEachFormat) {
    std::mt19937 rng(93);
    for (NumberFormat format : format_classes()) {
        PairFinder finder(format);
        for (uint32_t n : {1u, 300u, 3000u}) {
            for (const WordScene& scene : scenes_for(format, n, rng)) {
                const PairList expected = testing::lane_hit_pairs(scene, format);
                PairList pairs;
                finder.all_pairs(n, scene.view(), pairs);
                EXPECT_EQ(pairs, expected) << format.name() << " all pairs n=" << n;
                for (uint32_t cluster_above : {PairFinder::kClusterAbove, 0u}) {
                    finder.set_cluster_above(cluster_above);
                    finder.sweep(n, scene.view(), pairs);
                    EXPECT_EQ(pairs, expected) << format.name() << " sweep n=" << n << " cluster " << cluster_above;
                }
                if (HasFailure()) return;
            }
        }
        // A spread fixed scene is swept in a grid of cells, not along x alone.
        const WordScene spread = testing::fixed_scene(3000, format, 0.002, rng);
        PairList pairs;
        finder.sweep(3000, spread.view(), pairs);
        EXPECT_GT(finder.last_cells(), 1u) << format.name();
        EXPECT_EQ(pairs, testing::lane_hit_pairs(spread, format)) << format.name();
    }
}

}  // namespace
}  // namespace cdvp
