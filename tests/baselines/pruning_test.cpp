// The pruning baselines (hierarchical grid, box pruning) on what their
// structures find hard: sizes a hundred times apart, flat and point boxes,
// everything in one cell, inverted, NaN and unbounded boxes; and the choices
// they make (levels, SIMD width) made as documented.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "sw/baselines/box_pruning.h"
#include "sw/baselines/brute_force.h"
#include "sw/baselines/hierarchical_grid.h"
#include "tests/baselines/exact_pairs.h"
#include "tests/baselines/scenes.h"

namespace cdvp {
namespace {

using test::Boxes;

constexpr float kUnbounded = std::numeric_limits<float>::infinity();
constexpr float kNotANumber = std::numeric_limits<float>::quiet_NaN();


// Debris of edge 1 among a few slabs a hundred times larger, on a 1/8 grid.
Boxes debris_and_slabs(std::size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> at(0, 8 * 200);
    Boxes boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        const float size = i % 50 == 0 ? 100.0f : 1.0f;
        for (int axis = 0; axis < 3; ++axis) {
            boxes[i].min[axis] = float(at(rng)) / 8.0f;
            boxes[i].max[axis] = boxes[i].min[axis] + size;
        }
    }
    return boxes;
}

// Random boxes with some bounds made NaN, infinite, huge, swapped (min above
// max) or equal, on one axis at a time.
Boxes hostile_boxes(std::size_t n, uint32_t seed) {
    Boxes boxes = test::random_boxes(n, seed);
    std::mt19937 rng(seed);
    for (FloatBox& b : boxes) {
        const int axis = int(rng() % 3);
        switch (rng() % 10) {
            case 0: b.min[axis] = -kUnbounded; break;
            case 1: b.max[axis] = kUnbounded; break;
            case 2: b.min[axis] = kNotANumber; break;
            case 3: std::swap(b.min[axis], b.max[axis]); break;
            case 4: b.min[axis] = b.max[axis] = kUnbounded; break;
            case 5: b.min[axis] = -3e38f, b.max[axis] = 3e38f; break;
            case 6: b.max[axis] = b.min[axis]; break;
            default: break;
        }
    }
    return boxes;
}

class Pruning : public ::testing::TestWithParam<std::string> {
protected:
    std::unique_ptr<BroadPhase> phase_ = make_broad_phase(GetParam(), BaselineOptions{2});
};

TEST_P(Pruning, SizesAHundredTimesApart) {
    for (const std::size_t n : {2, 60, 3000}) test::expect_exact(*phase_, debris_and_slabs(n, uint32_t(n)), "debris");
}

TEST_P(Pruning, NaNInvertedAndUnboundedBoxes) {
    for (const uint32_t seed : {1u, 2u, 3u, 4u}) {
        const Boxes boxes = hostile_boxes(600, seed);
        PairList want = reference_pairs(boxes);
        ASSERT_GT(want.size(), 100u);
        test::expect_exact(*phase_, boxes, "hostile boxes, seed " + std::to_string(seed));
    }
}

TEST_P(Pruning, PointsFlatBoxesAndOneCrowdedSpot) {
    Boxes points(300), flat(300), same(200, FloatBox{{1, 1, 1}, {1, 1, 1}});
    for (std::size_t i = 0; i < points.size(); ++i) {
        const float x = float(i % 7), y = float(i % 5);
        points[i] = {{x, y, 0}, {x, y, 0}};
        flat[i] = {{x, y, 0}, {x + 1.5f, y + 0.5f, 0}};
    }
    test::expect_exact(*phase_, points, "points");
    test::expect_exact(*phase_, flat, "flat boxes");
    test::expect_exact(*phase_, same, "identical points");
}

INSTANTIATE_TEST_SUITE_P(Baselines, Pruning, ::testing::Values("prune", "prune_mt", "hgrid", "hgrid_mt"),
                         [](const auto& info) { return info.param; });

// The slabs go to a coarser level than the debris; a uniform scene needs one
// level (and the single-cell top level stays empty).
TEST(HierarchicalGrid, LargeBoxesGoToCoarserLevels) {
    HierarchicalGridBroadPhase grid(1, false);
    PairList pairs;
    grid.find_pairs(debris_and_slabs(3000, 7), pairs);
    ASSERT_GE(grid.level_count(), 2u);
    EXPECT_EQ(grid.level(0).boxes(), 3000u - 60u);
    std::size_t above = 0;
    for (std::size_t k = 1; k < grid.level_count(); ++k) above += grid.level(k).boxes();
    EXPECT_EQ(above, 60u);
    grid.find_pairs(test::random_boxes(3000, 7), pairs);
    EXPECT_EQ(grid.level(0).boxes(), 3000u);
    // No level holds more than twice as many cells as boxes (sparse scenes coarsen).
    for (std::size_t k = 0; k < grid.level_count(); ++k) EXPECT_LE(grid.level(k).cells(), 6000u);
}

// Past a few thousand boxes the multi-threaded grid files them in parts,
// one a thread: the same pairs, whatever the threads.
TEST(HierarchicalGrid, FilingInPartsKeepsEveryPair) {
    Boxes boxes = test::random_boxes(20000, 5);
    for (std::size_t i = 0; i < boxes.size(); i += 997) boxes[i] = {{0, 0, 0}, {kUnbounded, 3e38f, 1e6f}};
    const PairList want = reference_pairs(boxes);
    for (const unsigned threads : {2u, 3u, 8u}) {
        HierarchicalGridBroadPhase grid(threads, true);
        PairList got;
        grid.find_pairs(boxes, got);
        EXPECT_EQ(sorted(got), want) << threads << " threads";
    }
}

// An unbounded box lands in the top level, a single cell.
TEST(HierarchicalGrid, AnUnboundedBoxLivesInTheTopLevel) {
    Boxes boxes = test::random_boxes(500, 3);
    boxes.push_back({{-kUnbounded, -kUnbounded, -kUnbounded}, {kUnbounded, kUnbounded, kUnbounded}});
    HierarchicalGridBroadPhase grid(1, false);
    PairList pairs;
    grid.find_pairs(boxes, pairs);
    const auto& top = grid.level(grid.level_count() - 1);
    EXPECT_EQ(top.cells(), 1u);
    ASSERT_EQ(top.boxes(), 1u);
    EXPECT_EQ(top.entries[0].index, 500u);
    EXPECT_EQ(std::count_if(pairs.begin(), pairs.end(), [](const IndexPair& p) { return p.second == 500; }), 500);
}

TEST(BoxPruning, SimdWidthIsTheCpusWidest) {
    const BoxPruningBroadPhase prune(1, false);
#if defined(__x86_64__)
    EXPECT_EQ(prune.simd_width(), __builtin_cpu_supports("avx2") ? 8 : 4);
#else
    EXPECT_EQ(prune.simd_width(), 1);
#endif
}

// Every kernel the CPU can run finds the same pairs as the reference,
// whichever one the baseline picked.
TEST(BoxPruning, EveryKernelAgrees) {
    std::vector<PruneSweep> kernels{&prune_sweep_scalar};
#if defined(__x86_64__)
    kernels.push_back(&prune_sweep_sse2);
    if (__builtin_cpu_supports("avx2")) kernels.push_back(&prune_sweep_avx2);
#endif
    const Boxes boxes = hostile_boxes(900, 11);
    // Sorted by the lower bound on x, NaN boxes left out, padded with NaN.
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        bool nan = false;
        for (int a = 0; a < 3; ++a) nan = nan || std::isnan(boxes[i].min[a]) || std::isnan(boxes[i].max[a]);
        if (!nan) order.push_back(i);
    }
    const auto key = [&](uint32_t i) { return std::min(boxes[i].min[0], boxes[i].max[0]); };
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    std::vector<float> keys(order.size() + 8, kNotANumber), mins[3], maxs[3];
    for (int a = 0; a < 3; ++a) mins[a].assign(order.size() + 8, kNotANumber), maxs[a].assign(order.size() + 8, kNotANumber);
    for (std::size_t k = 0; k < order.size(); ++k) {
        keys[k] = key(order[k]);
        for (int a = 0; a < 3; ++a) mins[a][k] = boxes[order[k]].min[a], maxs[a][k] = boxes[order[k]].max[a];
    }
    const PruneArrays arrays{keys.data(), {mins[0].data(), mins[1].data(), mins[2].data()},
                             {maxs[0].data(), maxs[1].data(), maxs[2].data()}, order.data(),
                             uint32_t(order.size()), 0};
    for (const PruneSweep kernel : kernels) {
        PairList pairs;
        kernel(arrays, 0, arrays.count, pairs, PairBudget::kUnlimited);
        EXPECT_EQ(sorted(pairs), reference_pairs(boxes));
    }
}

}  // namespace
}  // namespace cdvp
