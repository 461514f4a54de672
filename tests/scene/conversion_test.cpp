#include "sw/scene/conversion.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace cdvp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kInfF = std::numeric_limits<float>::infinity();
constexpr float kDenormMin = 0x1p-149f;

// Compares bit patterns, so -0 and +0 differ.
void expect_same_float(float expected, float actual) {
    EXPECT_EQ(std::signbit(expected), std::signbit(actual)) << expected << " vs " << actual;
    EXPECT_EQ(expected, actual);
}

TEST(Conversion, ExactValuesKept) {
    for (double v : {0.0, 1.0, -1.0, 0.5, 1.5, 1e10 /* 2^10*5^10 exact */, 16777216.0,
                     double(FLT_MAX), -double(FLT_MAX), double(FLT_MIN), kInf, -kInf,
                     1.00000011920928955078125}) {
        expect_same_float(static_cast<float>(v), round_down_to_float(v));
        expect_same_float(static_cast<float>(v), round_up_to_float(v));
        EXPECT_EQ(static_cast<double>(round_down_to_float(v)), v);
    }
}

TEST(Conversion, SignedZeroKept) {
    expect_same_float(-0.0f, round_down_to_float(-0.0));
    expect_same_float(-0.0f, round_up_to_float(-0.0));
    expect_same_float(0.0f, round_down_to_float(0.0));
    expect_same_float(0.0f, round_up_to_float(0.0));
}

TEST(Conversion, DenormalsKept) {
    for (float f : {kDenormMin, -kDenormMin, 3 * kDenormMin, FLT_MIN / 2, -FLT_MIN / 4}) {
        ASSERT_NE(f, 0.0f);
        expect_same_float(f, round_down_to_float(static_cast<double>(f)));
        expect_same_float(f, round_up_to_float(static_cast<double>(f)));
    }
}

TEST(Conversion, RoundsInTheRightDirection) {
    for (double v : {0.1, 1.0 / 3.0, -0.1, -1.0 / 3.0, 1e-40, 123456789.123, -2.7e38}) {
        float down = round_down_to_float(v);
        float up = round_up_to_float(v);
        EXPECT_LT(static_cast<double>(down), v) << v;
        EXPECT_GT(static_cast<double>(up), v) << v;
        EXPECT_EQ(std::nextafterf(down, kInfF), up) << v;  // adjacent floats
    }
    EXPECT_EQ(round_down_to_float(0.1), 0x1.999998p-4f);
    EXPECT_EQ(round_up_to_float(0.1), 0x1.99999ap-4f);
    EXPECT_EQ(round_down_to_float(1.0 / 3.0), 0x1.555554p-2f);
    EXPECT_EQ(round_up_to_float(1.0 / 3.0), 0x1.555556p-2f);
}

TEST(Conversion, BeyondFloatRangeGoesOutward) {
    EXPECT_EQ(round_down_to_float(1e300), FLT_MAX);
    EXPECT_EQ(round_up_to_float(1e300), kInfF);
    EXPECT_EQ(round_down_to_float(-1e300), -kInfF);
    EXPECT_EQ(round_up_to_float(-1e300), -FLT_MAX);
    // Just above FLT_MAX: nearest rounding would give FLT_MAX.
    double above = std::nextafter(double(FLT_MAX), kInf);
    EXPECT_EQ(round_down_to_float(above), FLT_MAX);
    EXPECT_EQ(round_up_to_float(above), kInfF);
}

TEST(Conversion, TinyValues) {
    expect_same_float(0.0f, round_down_to_float(1e-50));
    expect_same_float(kDenormMin, round_up_to_float(1e-50));
    expect_same_float(-kDenormMin, round_down_to_float(-1e-50));
    expect_same_float(-0.0f, round_up_to_float(-1e-50));
}

// The step taken without nextafterf is nextafterf's: doubles of every
// magnitude and sign, near float boundaries, zeros, denormals and the ends.
TEST(Conversion, StepsAsNextafterfDoes) {
    const auto down_reference = [](double v) {
        float f = static_cast<float>(v);
        return static_cast<double>(f) > v ? std::nextafterf(f, -kInfF) : f;
    };
    const auto up_reference = [](double v) {
        float f = static_cast<float>(v);
        return static_cast<double>(f) < v ? std::nextafterf(f, kInfF) : f;
    };
    std::vector<double> values{0.0, -0.0, 1e-46, -1e-46, 1e-300, -1e-300, 0x1p-149, -0x1p-149, 0x1.8p-149,
                               -0x1.8p-149, FLT_MIN, -FLT_MIN, FLT_MAX, -FLT_MAX, 3.5e38, -3.5e38, 1e300, -1e300,
                               kInf, -kInf, 1.0 / 3, -1.0 / 3, 16777217.0, -16777217.0};
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<uint64_t> bits;
    for (int k = 0; k < 200000; ++k) {
        double v;
        const uint64_t b = bits(rng);
        std::memcpy(&v, &b, sizeof v);
        if (!std::isnan(v)) values.push_back(v);
        values.push_back(std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), k % 300 - 150));
    }
    for (const double v : values) {
        const float down = round_down_to_float(v), up = round_up_to_float(v);
        const float down_expected = down_reference(v), up_expected = up_reference(v);
        ASSERT_EQ(std::memcmp(&down, &down_expected, sizeof down), 0) << std::hexfloat << v;
        ASSERT_EQ(std::memcmp(&up, &up_expected, sizeof up), 0) << std::hexfloat << v;
    }
}

TEST(Conversion, BoxMinsDownMaxesUp) {
    Box b{{0.1, -0.1, 1.0}, {0.2, 1e300, 1.0}};
    FloatBox f = to_float_box(b);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(static_cast<double>(f.min[axis]), b.min[axis]);
        EXPECT_GE(static_cast<double>(f.max[axis]), b.max[axis]);
    }
    EXPECT_EQ(f.max[1], kInfF);
    EXPECT_EQ(f.min[2], 1.0f);
    EXPECT_EQ(f.max[2], 1.0f);
    std::vector<FloatBox> all = to_float_boxes({b, b});
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[1].min[0], f.min[0]);
}

bool overlap(const Box& a, const Box& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis])) return false;
    }
    return true;
}

bool overlap(const FloatBox& a, const FloatBox& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis])) return false;
    }
    return true;
}

// Boxes that overlap or touch in double keep overlapping in float. Values are
// drawn at many scales and the second box is often placed to touch the first
// exactly or to nearly touch it, where rounding matters.
TEST(Conversion, OverlapSurvivesConversion) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> exponent(-160, 140);
    std::uniform_int_distribution<int> mode(0, 3);
    auto value = [&] {
        double v = std::ldexp(unit(rng), exponent(rng));
        return unit(rng) < 0.5 ? -v : v;
    };
    int overlapping = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        Box a;
        Box b;
        for (int axis = 0; axis < 3; ++axis) {
            double x = value();
            double y = value();
            a.min[axis] = std::min(x, y);
            a.max[axis] = std::max(x, y);
            double w = std::abs(value());
            switch (mode(rng)) {
            case 0:  // b starts where a ends
                b.min[axis] = a.max[axis];
                break;
            case 1:  // b ends where a starts
                b.min[axis] = a.min[axis] - w;
                break;
            case 2:  // b starts just inside a
                b.min[axis] = std::nextafter(a.max[axis], -kInf);
                break;
            default:  // somewhere inside a
                b.min[axis] = a.min[axis] + (a.max[axis] - a.min[axis]) * unit(rng);
                break;
            }
            b.max[axis] = b.min[axis] + w;
            if (b.max[axis] < a.min[axis]) b.max[axis] = a.min[axis];
        }
        if (!overlap(a, b)) continue;
        ++overlapping;
        ASSERT_TRUE(overlap(to_float_box(a), to_float_box(b))) << "trial " << trial;
    }
    EXPECT_GT(overlapping, 100000);
}

}  // namespace
}  // namespace cdvp
