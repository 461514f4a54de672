// The host's quantiser: outward rounding, and the property that matters, no
// pair of the float32 comparison is ever lost in any fixed format.
#include "platform/driver/quantiser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace cdvp {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenorm = std::numeric_limits<float>::denorm_min();

FloatBox box(float x0, float y0, float z0, float x1, float y1, float z1) { return {{x0, y0, z0}, {x1, y1, z1}}; }

// All pairs of the boxes as the board's words in `format` would compare them.
PairList pairs_in(NumberFormat format, const std::vector<FloatBox>& boxes) {
    const Quantiser quantiser(format, boxes);
    std::vector<std::array<uint32_t, kCoordinates>> words(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t c = 0; c < kCoordinates; ++c) words[i][c] = quantiser.word(boxes[i], c);
    }
    PairList pairs;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t j = i + 1; j < boxes.size(); ++j) {
            if (ComparisonUnit::lane_hit(format, words[i].data(), words[j].data())) pairs.push_back({i, j});
        }
    }
    return pairs;
}

// Every pair of the float32 reference is among the pair set of every fixed
// format; returns the extra pairs summed over the formats.
std::size_t expect_no_pair_lost(const std::vector<FloatBox>& boxes, const std::string& what) {
    const PairList reference = pairs_in(NumberFormat::float32(), boxes);
    std::size_t extra = 0;
    for (uint32_t k = NumberFormat::kMinFixedBits; k <= NumberFormat::kMaxFixedBits; ++k) {
        const PairList fixed = pairs_in(NumberFormat::fixed(k), boxes);
        EXPECT_TRUE(std::includes(fixed.begin(), fixed.end(), reference.begin(), reference.end(),
                                  [](const IndexPair& a, const IndexPair& b) {
                                      return a.first != b.first ? a.first < b.first : a.second < b.second;
                                  }))
            << what << ": fixed" << k << " lost a pair of the float32 reference";
        extra += fixed.size() - std::min(fixed.size(), reference.size());
    }
    return extra;
}

TEST(Quantiser, RoundsMinsDownAndMaxesUpOverTheSceneBounds) {
    const std::vector<FloatBox> boxes = {box(0, 0, 0, 1, 1, 1), box(0.3f, 2, 0, 3, 4, 1)};
    const Quantiser q(NumberFormat::fixed(8), boxes);
    EXPECT_EQ(q.low(0), 0.0);
    EXPECT_EQ(q.high(0), 3.0);
    EXPECT_EQ(q.min_code(0, 0.0f), 0u);
    EXPECT_EQ(q.max_code(0, 3.0f), 255u);
    EXPECT_EQ(q.min_code(0, 1.0f), 85u);  // 255 / 3 exactly
    EXPECT_EQ(q.max_code(0, 1.0f), 85u);
    EXPECT_EQ(q.min_code(0, 0.3f), 25u);  // 25.5 down
    EXPECT_EQ(q.max_code(0, 0.3f), 26u);  // and up
    EXPECT_EQ(q.word(boxes[1], kMinY), 127u);  // y over [0, 4]: 2 -> 127.5 down
    EXPECT_EQ(q.word(boxes[1], kMaxY), 255u);
}

TEST(Quantiser, InfinitiesNansAndDegenerateAxes) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<FloatBox> boxes = {box(-kInf, 5, 1, kInf, 5, 2), box(0, 5, nan, 10, 5, nan)};
    const Quantiser q(NumberFormat::fixed(16), boxes);
    EXPECT_EQ(q.min_code(0, -kInf), 0u);
    EXPECT_EQ(q.max_code(0, kInf), 65535u);
    EXPECT_EQ(q.min_code(0, kInf), 65535u);
    EXPECT_EQ(q.max_code(0, -kInf), 0u);
    EXPECT_EQ(q.min_code(2, nan), 0u);
    EXPECT_EQ(q.max_code(2, nan), 65535u);
    EXPECT_EQ(q.min_code(1, 5.0f), 0u) << "a zero-width axis maps to 0";
    EXPECT_EQ(q.max_code(1, 5.0f), 0u);
    // No finite bound at all on an axis: finite values still map to 0.
    const Quantiser unbounded(NumberFormat::fixed(8), {box(-kInf, -kInf, -kInf, kInf, kInf, kInf)});
    EXPECT_EQ(unbounded.min_code(0, 3.0f), 0u);
    EXPECT_EQ(unbounded.max_code(0, kInf), 255u);
}

TEST(Quantiser, Float32WordsAreTheFloatsBits) {
    const std::vector<FloatBox> boxes = {box(-0.0f, 1, 2, 3, kInf, kDenorm)};
    const Quantiser q(NumberFormat::float32(), boxes);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const float value = c < 3 ? boxes[0].min[c] : boxes[0].max[c - 3];
        EXPECT_EQ(q.word(boxes[0], c), ComparisonUnit::as_bits(value));
    }
}

TEST(Quantiser, CodesAreMonotoneInTheValue) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> value(-1e6f, 1e6f);
    for (uint32_t k : {8u, 13u, 24u, 32u}) {
        const Quantiser q(NumberFormat::fixed(k), {box(-1e6f, 0, 0, 1e6f, 1, 1)});
        for (int n = 0; n < 5000; ++n) {
            float a = value(rng), b = value(rng);
            if (b < a) std::swap(a, b);
            EXPECT_LE(q.min_code(0, a), q.min_code(0, b));
            EXPECT_LE(q.max_code(0, a), q.max_code(0, b));
            EXPECT_LE(q.min_code(0, a), q.max_code(0, a));
        }
    }
}

TEST(Quantiser, NoPairOfTheFloat32ReferenceIsLostInRandomScenes) {
    std::mt19937 rng(6);
    std::size_t extra = 0;
    for (int scene = 0; scene < 12; ++scene) {
        const float extent = std::pow(10.0f, static_cast<float>(scene % 6) * 2 - 4);
        std::uniform_real_distribution<float> corner(-extent, extent), side(0, extent / 4);
        std::vector<FloatBox> boxes;
        for (int i = 0; i < 60; ++i) {
            FloatBox b;
            for (int axis = 0; axis < 3; ++axis) {
                b.min[axis] = corner(rng);
                b.max[axis] = b.min[axis] + side(rng);
            }
            boxes.push_back(b);
        }
        extra += expect_no_pair_lost(boxes, "random scene " + std::to_string(scene));
    }
    EXPECT_GT(extra, 0u) << "8-bit codes over these scenes must add pairs";
}

TEST(Quantiser, NoPairOfTheFloat32ReferenceIsLostInHostileScenes) {
    const float next_one = std::nextafter(1.0f, 2.0f);
    // Touching faces, a one-ulp gap, and boxes at the scene bounds.
    expect_no_pair_lost({box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 2, 1, 1), box(next_one, 1, 1, 3, 2, 2),
                         box(3, 2, 2, 3, 2, 2), box(0, 0, 0, 0, 0, 0)},
                        "touching");
    // Degenerate zero-width axes, and a flat plate.
    expect_no_pair_lost({box(1, 5, 1, 2, 5, 2), box(1.5f, 5, 1.5f, 3, 5, 3), box(0, 5, 0, 9, 5, 9)}, "zero width");
    // Huge ranges beside tiny boxes.
    expect_no_pair_lost({box(-1e30f, -1e30f, -1e30f, -1e30f, -1e30f, -1e30f), box(1e30f, 1e30f, 1e30f, 1e30f, 1e30f, 1e30f),
                         box(0, 0, 0, 1e-3f, 1e-3f, 1e-3f), box(1e-3f, 1e-3f, 1e-3f, 2e-3f, 2e-3f, 2e-3f),
                         box(-3.4e38f, 0, 0, 3.4e38f, 0, 0)},
                        "huge range");
    // Denormals and signed zeros.
    expect_no_pair_lost({box(-0.0f, -0.0f, -0.0f, 0, 0, 0), box(0, 0, 0, kDenorm, kDenorm, kDenorm),
                         box(2 * kDenorm, 0, 0, 3 * kDenorm, 0, 0), box(-kDenorm, -kDenorm, -kDenorm, -0.0f, -0.0f, -0.0f)},
                        "denormals");
    // Infinities: slabs, half-spaces and points at infinity.
    expect_no_pair_lost({box(-kInf, -kInf, -1, kInf, kInf, 0), box(0, 0, 0, 1, 1, 1), box(kInf, kInf, kInf, kInf, kInf, kInf),
                         box(5, 5, 5, kInf, kInf, kInf), box(-kInf, -kInf, -kInf, -kInf, -kInf, -kInf),
                         box(-kInf, 2, 2, -5, 3, 3)},
                        "infinities");
    // All boxes equal, one box, none.
    expect_no_pair_lost(std::vector<FloatBox>(7, box(1, 2, 3, 4, 5, 6)), "all equal");
    expect_no_pair_lost({box(1, 2, 3, 4, 5, 6)}, "one box");
    expect_no_pair_lost({}, "no box");
    // Dense near-touching grid: many pairs decided by one ulp.
    std::vector<FloatBox> grid;
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const float x = 0.1f * static_cast<float>(i), y = 0.1f * static_cast<float>(j);
            grid.push_back(box(x, y, 0, std::nextafter(x + 0.1f, 0.0f), y + 0.1f, 1));
        }
    }
    expect_no_pair_lost(grid, "near-touching grid");
}

}  // namespace
}  // namespace cdvp
