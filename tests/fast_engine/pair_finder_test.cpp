// The fast engine's pair search against the comparison unit's own all-pairs test.
#include "models/fast_engine/pair_finder.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

using testing::WordScene;

// Both algorithms, and the choice between them, give exactly the reference.
void expect_exact(PairFinder& finder, const WordScene& scene, const char* what) {
    const PairList expected = testing::lane_hit_pairs(scene);
    PairList pairs;
    finder.all_pairs(scene.size(), scene.view(), pairs);
    EXPECT_EQ(pairs, expected) << what << " all pairs, n=" << scene.size();
    finder.sweep(scene.size(), scene.view(), pairs);
    EXPECT_EQ(pairs, expected) << what << " sweep, n=" << scene.size();
    finder.find(scene.size(), scene.view(), pairs);
    EXPECT_EQ(pairs, expected) << what << " find, n=" << scene.size();
}

TEST(PairFinder, EqualsTheComparisonUnitOnEveryKindOfScene) {
    std::mt19937 rng(7);
    PairFinder finder;  // reused: scratch from a larger scene must not leak into a smaller one
    for (uint32_t n : {0u, 1u, 2u, 3u, 7u, 8u, 9u, 17u, 200u, 511u, 512u, 513u, 1500u, 3000u}) {
        const float extent = 10.0f * std::cbrt(static_cast<float>(n) + 1);
        expect_exact(finder, testing::random_scene(n, extent, 2.0f, rng), "random");
        expect_exact(finder, testing::clustered_scene(n, 5, rng), "clustered");
        WordScene special = testing::random_scene(n, extent, 3.0f, rng);
        testing::sprinkle_special_values(special, 0.02, rng);
        expect_exact(finder, special, "special values");
        expect_exact(finder, testing::denormal_scene(n, rng), "denormals");
    }
    for (uint32_t n : {2u, 100u, 700u}) expect_exact(finder, testing::overlapping_scene(n, rng), "overlapping");
}

TEST(PairFinder, SpreadScenesAreSweptInAGridOfCells) {
    std::mt19937 rng(8);
    const WordScene scene = testing::random_scene(20000, 80.0f, 2.0f, rng);
    PairList pairs;
    PairFinder finder;
    finder.sweep(scene.size(), scene.view(), pairs);
    EXPECT_GT(finder.last_cells(), 100u);
    PairList expected;
    finder.all_pairs(scene.size(), scene.view(), expected);
    EXPECT_GT(expected.size(), 1000u);
    EXPECT_EQ(pairs, expected);
}

// A few infinite, signed-zero, denormal, NaN and inverted bounds among many
// ordinary boxes: the grid stays, and the odd boxes land in the right cells.
TEST(PairFinder, SpecialValuesInsideAGrid) {
    std::mt19937 rng(11);
    for (int round = 0; round < 3; ++round) {
        WordScene scene = testing::random_scene(6000, 120.0f, 3.0f, rng);
        testing::sprinkle_special_values(scene, 0.003, rng);
        PairFinder finder;
        PairList pairs, expected;
        finder.sweep(scene.size(), scene.view(), pairs);
        EXPECT_GT(finder.last_cells(), 16u);
        finder.all_pairs(scene.size(), scene.view(), expected);
        EXPECT_EQ(pairs, expected);
    }
}

// Boxes spanning three or more cells on an axis (placed cell by cell on the
// general path) among boxes spanning one or two (placed without a branch),
// with and without grouping the boxes by cell first.
TEST(PairFinder, WideBoxesAmongSmallOnesWithAndWithoutGroupingByCell) {
    std::mt19937 rng(12);
    WordScene scene = testing::random_scene(5000, 100.0f, 2.0f, rng);
    std::uniform_int_distribution<uint32_t> pick(0, scene.size() - 1);
    for (int k = 0; k < 40; ++k) {
        const uint32_t i = pick(rng);
        const Coordinate axis_min = k % 2 == 0 ? kMinY : kMinZ;
        const auto axis_max = static_cast<Coordinate>(axis_min + 3);
        const float low = ComparisonUnit::as_float(scene.words[axis_min][i]);
        scene.words[axis_max][i] = ComparisonUnit::as_bits(low + 40.0f);  // many cells wide
    }
    testing::sprinkle_special_values(scene, 0.002, rng);
    PairList expected;
    PairFinder finder;
    finder.all_pairs(scene.size(), scene.view(), expected);
    for (uint32_t cluster_above : {PairFinder::kClusterAbove, 0u}) {
        finder.set_cluster_above(cluster_above);
        PairList pairs;
        finder.sweep(scene.size(), scene.view(), pairs);
        EXPECT_GT(finder.last_cells(), 16u);
        EXPECT_EQ(pairs, expected) << "grouped above " << cluster_above;
    }
}

// A box reaching to infinity on y and z touches every cell: with many such
// boxes the grid would hold N x cells entries, so the sweep goes without it.
TEST(PairFinder, BoxesSpanningEverythingDropTheGrid) {
    std::mt19937 rng(9);
    WordScene scene = testing::random_scene(4000, 200.0f, 2.0f, rng);
    for (uint32_t i = 0; i < scene.size(); i += 2) {
        for (Coordinate c : {kMinY, kMinZ}) scene.words[c][i] = 0xFF80'0000u;  // -inf
        for (Coordinate c : {kMaxY, kMaxZ}) scene.words[c][i] = 0x7F80'0000u;  // +inf
    }
    PairFinder finder;
    PairList pairs;
    finder.sweep(scene.size(), scene.view(), pairs);
    EXPECT_EQ(finder.last_cells(), 1u);
    EXPECT_EQ(pairs, testing::lane_hit_pairs(scene));
}

TEST(PairFinder, NanBoundsMeetNothingAndSignedZerosMeet) {
    // Box 0 touches box 1 at x = -0 / +0; box 2 has one NaN bound; box 3
    // reaches to infinity and meets everything without a NaN.
    const std::vector<FloatBox> boxes = {
        {{-1, 0, 0}, {-0.0f, 1, 1}},
        {{0.0f, 0, 0}, {1, 1, 1}},
        {{0, 0, 0}, {1, std::numeric_limits<float>::quiet_NaN(), 1}},
        {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}},
    };
    WordScene scene = WordScene::from_boxes(boxes);
    const PairList expected = {{0, 1}, {0, 3}, {1, 3}};
    PairFinder finder;
    PairList pairs;
    finder.all_pairs(scene.size(), scene.view(), pairs);
    EXPECT_EQ(pairs, expected);
    // The same boxes among 600 far-away ones, so that the sweep runs.
    std::mt19937 rng(10);
    WordScene padded = testing::random_scene(600, 1.0f, 0.5f, rng);
    for (auto& column : padded.words) {
        for (uint32_t& word : column) word = ComparisonUnit::as_bits(ComparisonUnit::as_float(word) + 1000.0f);
    }
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        padded.words[c].insert(padded.words[c].begin(), scene.words[c].begin(), scene.words[c].end());
    }
    finder.sweep(padded.size(), padded.view(), pairs);
    EXPECT_EQ(pairs, testing::lane_hit_pairs(padded));
    EXPECT_TRUE(std::find(pairs.begin(), pairs.end(), IndexPair{0, 1}) != pairs.end());
    EXPECT_TRUE(std::none_of(pairs.begin(), pairs.end(), [](const IndexPair& p) { return p.first == 2 || p.second == 2; }));
}

}  // namespace
}  // namespace cdvp
