// The cheap pair count against comparing every pair, on scenes built to
// catch a sweep's mistakes: touching faces, identical boxes, ties on the
// swept axis, signed zeros, boxes whose minimum exceeds their maximum, NaN.
#include "models/common/pair_count.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace cdvp {
namespace {

FloatBox box(float x0, float y0, float z0, float x1, float y1, float z1) { return FloatBox{{x0, y0, z0}, {x1, y1, z1}}; }

TEST(PairCount, ClosedIntervalsAsTheBoard) {
    PairCounter counter;
    // Touching on a face, an edge, a corner: all overlap; a gap of one ulp does not.
    const float after_one = std::nextafter(1.0f, 2.0f);
    EXPECT_EQ(counter.count({box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 2, 1, 1)}), 1u);
    EXPECT_EQ(counter.count({box(0, 0, 0, 1, 1, 1), box(1, 1, 1, 2, 2, 2)}), 1u);
    EXPECT_EQ(counter.count({box(0, 0, 0, 1, 1, 1), box(after_one, 0, 0, 2, 1, 1)}), 0u);
    EXPECT_EQ(counter.count({box(-0.0f, 0, 0, -0.0f, 1, 1), box(0.0f, 0, 0, 0.0f, 1, 1)}), 1u);
    // Identical boxes: every pair of them.
    EXPECT_EQ(counter.count(std::vector<FloatBox>(7, box(0, 0, 0, 1, 1, 1))), 21u);
    // NaN overlaps nothing; an inverted box only what its bounds allow.
    EXPECT_EQ(counter.count({box(NAN, 0, 0, 1, 1, 1), box(0, 0, 0, 1, 1, 1), box(0, 0, 0, 1, 1, 1)}), 1u);
    const std::vector<FloatBox> inverted{box(0, 0, 0, 2, 2, 2), box(1.5f, 0, 0, 0.5f, 1, 1)};
    EXPECT_EQ(counter.count(inverted), count_pairs_brute_force(inverted));
    EXPECT_EQ(counter.count({}), 0u);
    EXPECT_EQ(counter.count({box(0, 0, 0, 1, 1, 1)}), 0u);
}

// Coordinates on a coarse grid make ties and touching boxes common.
std::vector<FloatBox> grid_scene(std::size_t n, int cells, int largest, std::mt19937& rng) {
    std::uniform_int_distribution<int> corner(-cells, cells), side(0, largest), pick(0, 9);
    std::vector<FloatBox> boxes(n);
    for (std::size_t k = 0; k < n; ++k) {
        if (k > 0 && pick(rng) == 0) {  // a copy of an earlier box
            boxes[k] = boxes[std::uniform_int_distribution<std::size_t>(0, k - 1)(rng)];
            continue;
        }
        for (int a = 0; a < 3; ++a) {
            boxes[k].min[a] = 0.25f * static_cast<float>(corner(rng));
            boxes[k].max[a] = boxes[k].min[a] + 0.25f * static_cast<float>(side(rng));
        }
        if (pick(rng) == 1) std::swap(boxes[k].min[0], boxes[k].max[0]);  // inverted on one axis
    }
    return boxes;
}

TEST(PairCount, MatchesEveryPairComparedOnRandomScenes) {
    std::mt19937 rng(2024);
    PairCounter counter;
    uint64_t checked = 0;
    for (std::size_t n : {2u, 3u, 17u, 100u, 600u, 1500u}) {
        for (int largest : {0, 1, 4, 12}) {
            const std::vector<FloatBox> boxes = grid_scene(n, 16, largest, rng);
            const uint64_t expected = count_pairs_brute_force(boxes);
            EXPECT_EQ(counter.count(boxes), expected) << "n=" << n << " largest=" << largest;
            checked += expected;
        }
        std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f), side(0.0f, 8.0f);
        std::vector<FloatBox> boxes(n);
        for (FloatBox& b : boxes) {
            for (int a = 0; a < 3; ++a) b.min[a] = coordinate(rng), b.max[a] = b.min[a] + side(rng);
        }
        EXPECT_EQ(counter.count(boxes), count_pairs_brute_force(boxes)) << "n=" << n << " continuous";
    }
    EXPECT_GT(checked, 10000u) << "the scenes must hold many pairs for the check to mean anything";
}

// Both algorithms on every scene whatever its size, and scenes that stress a
// grid: unbounded and huge boxes (filed nowhere, tested against all), NaN,
// inverted boxes, every box in one cell, one axis without extent.
TEST(PairCount, TheGridAndTheSweepCountAsComparingEveryPair) {
    std::mt19937 rng(7);
    PairCounter counter;
    uint64_t checked = 0;
    for (std::size_t n : {0u, 1u, 2u, 40u, 700u, 2500u}) {
        for (int largest : {0, 2, 12}) {
            std::vector<FloatBox> boxes = grid_scene(n, 16, largest, rng);
            for (std::size_t k = 0; k < boxes.size(); k += 97) boxes[k].max[k % 3] = INFINITY;
            for (std::size_t k = 5; k < boxes.size(); k += 131) boxes[k].min[1] = -INFINITY;
            for (std::size_t k = 9; k < boxes.size(); k += 211) boxes[k] = box(-1e30f, -1e30f, -1e30f, 1e30f, 1e30f, 1e30f);
            for (std::size_t k = 3; k < boxes.size(); k += 173) boxes[k].min[2] = NAN;
            const uint64_t expected = count_pairs_brute_force(boxes);
            EXPECT_EQ(counter.count_by_grid(boxes), expected) << "grid n=" << n << " largest=" << largest;
            EXPECT_EQ(counter.count_by_sweep(boxes), expected) << "sweep n=" << n << " largest=" << largest;
            checked += expected;
        }
        std::vector<FloatBox> flat(n, box(0, 0, 0, 0, 0, 0));  // no extent on any axis: one cell
        for (std::size_t k = 0; k < n; ++k) flat[k].min[0] = flat[k].max[0] = static_cast<float>(k % 5);
        EXPECT_EQ(counter.count_by_grid(flat), count_pairs_brute_force(flat)) << "flat n=" << n;
    }
    EXPECT_GT(checked, 10000u);
}

}  // namespace
}  // namespace cdvp
