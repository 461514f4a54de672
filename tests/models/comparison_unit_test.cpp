#include "models/comparison_unit/comparison_unit.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "models/board/board_core.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenormMin = std::numeric_limits<float>::denorm_min();

FloatBox box(float x0, float y0, float z0, float x1, float y1, float z1) { return {{x0, y0, z0}, {x1, y1, z1}}; }
FloatBox unit_cube_at(float x, float y, float z) { return box(x, y, z, x + 1, y + 1, z + 1); }

// The lane test in both argument orders, and the whole board on the same two
// boxes: all three must agree.
bool overlap(const FloatBox& a, const FloatBox& b) {
    const float fa[6] = {a.min[0], a.min[1], a.min[2], a.max[0], a.max[1], a.max[2]};
    const float fb[6] = {b.min[0], b.min[1], b.min[2], b.max[0], b.max[1], b.max[2]};
    const bool ab = ComparisonUnit::lane_hit(fa, fb);
    EXPECT_EQ(ab, ComparisonUnit::lane_hit(fb, fa)) << "the test must be symmetric";
    BoardConfig config;
    config.m = 1;
    BoardCore core(config, 2);
    const testing::CoreRun run = testing::run_core(core, {a, b});
    EXPECT_EQ(run.pairs.size(), ab ? 1u : 0u) << "board and lane disagree";
    return ab;
}

TEST(ComparisonUnit, TouchingFacesEdgesAndCornersOverlap) {
    const FloatBox a = unit_cube_at(0, 0, 0);
    EXPECT_TRUE(overlap(a, unit_cube_at(1, 0, 0))) << "face";
    EXPECT_TRUE(overlap(a, unit_cube_at(1, 1, 0))) << "edge";
    EXPECT_TRUE(overlap(a, unit_cube_at(1, 1, 1))) << "corner";
    EXPECT_TRUE(overlap(a, unit_cube_at(-1, -1, -1))) << "corner, other side";
}

TEST(ComparisonUnit, OneUlpGapIsNotAnOverlap) {
    const FloatBox a = unit_cube_at(0, 0, 0);
    const float next = std::nextafter(1.0f, 2.0f);
    EXPECT_FALSE(overlap(a, box(next, 0, 0, 3, 1, 1)));
    EXPECT_FALSE(overlap(a, box(0, next, 0, 1, 3, 1)));
    EXPECT_FALSE(overlap(a, box(0, 0, next, 1, 1, 3)));
    const float below = std::nextafter(0.0f, -1.0f);
    EXPECT_FALSE(overlap(a, box(-2, -2, -2, 1, 1, below)));
}

TEST(ComparisonUnit, NegativeZeroEqualsPositiveZero) {
    EXPECT_TRUE(overlap(box(-1, -1, -1, -0.0f, 1, 1), box(0.0f, -1, -1, 1, 1, 1)));
    EXPECT_TRUE(overlap(box(-1, -1, -1, 0.0f, 1, 1), box(-0.0f, -1, -1, 1, 1, 1)));
}

TEST(ComparisonUnit, DenormalsAreKept) {
    // Flushed to zero these would touch; kept, they are one denormal apart.
    EXPECT_FALSE(overlap(box(-1, -1, -1, 0.0f, 1, 1), box(kDenormMin, -1, -1, 1, 1, 1)));
    EXPECT_TRUE(overlap(box(-1, -1, -1, kDenormMin, 1, 1), box(kDenormMin, -1, -1, 1, 1, 1)));
    EXPECT_FALSE(overlap(box(-1, -1, -1, kDenormMin, 1, 1), box(2 * kDenormMin, -1, -1, 1, 1, 1)));
    EXPECT_FALSE(overlap(box(-1, -1, -1, -kDenormMin, 1, 1), box(0.0f, -1, -1, 1, 1, 1)));
}

TEST(ComparisonUnit, InfinitiesCompareAsNumbers) {
    const FloatBox slab = box(-kInf, -1, -kInf, kInf, 0, kInf);
    EXPECT_TRUE(overlap(slab, unit_cube_at(1e30f, 0, -1e30f))) << "resting on an infinite ground slab";
    EXPECT_FALSE(overlap(slab, unit_cube_at(0, std::nextafter(0.0f, 1.0f), 0)));
    EXPECT_TRUE(overlap(slab, box(-kInf, -kInf, -kInf, -kInf, kInf, -kInf))) << "both at -inf touch";
    EXPECT_FALSE(overlap(box(kInf, 0, 0, kInf, 1, 1), box(-kInf, 0, 0, FLT_MAX, 1, 1)));
    EXPECT_TRUE(overlap(box(FLT_MAX, 0, 0, kInf, 1, 1), box(-kInf, 0, 0, FLT_MAX, 1, 1)));
}

TEST(ComparisonUnit, IdenticalAndZeroWidthBoxes) {
    const FloatBox a = box(1, 2, 3, 4, 5, 6);
    EXPECT_TRUE(overlap(a, a));
    const FloatBox point = box(2, 3, 4, 2, 3, 4);
    EXPECT_TRUE(overlap(point, point));
    EXPECT_TRUE(overlap(a, point)) << "a point inside";
    EXPECT_TRUE(overlap(a, box(4, 5, 6, 4, 5, 6))) << "a point on the corner";
    EXPECT_TRUE(overlap(box(0, 0, 0, 0, 10, 10), box(0, 1, 1, 5, 2, 2))) << "a flat box";
    EXPECT_FALSE(overlap(point, box(2, 3, std::nextafter(4.0f, 5.0f), 2, 3, 5)));
}

TEST(ComparisonUnit, EvaluatesOnlyValidLanes) {
    const uint32_t m = 3;  // 5 lanes
    CoordinateMemories memories = {CoordinateMemory(m, 8), CoordinateMemory(m, 8), CoordinateMemory(m, 8),
                                   CoordinateMemory(m, 8), CoordinateMemory(m, 8), CoordinateMemory(m, 8)};
    for (uint32_t i = 0; i < 8; ++i) {  // all boxes identical: every valid lane hits
        for (uint32_t c = 0; c < kCoordinates; ++c) memories[c].write(i, ComparisonUnit::as_bits(c < 3 ? 0.f : 1.f));
    }
    for (auto& memory : memories) {
        for (uint32_t p = 0; p < memory.ports(); ++p) memory.clock_read(p, p);
    }
    ComparisonUnit unit(5, ComparisonUnitConfig{});
    EXPECT_EQ(unit.evaluate(memories, 5), 0b11111u);
    EXPECT_EQ(unit.evaluate(memories, 2), 0b00011u);
    EXPECT_THROW(ComparisonUnit(64, ComparisonUnitConfig{}), std::invalid_argument);
}

}  // namespace
}  // namespace cdvp
