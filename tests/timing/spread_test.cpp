#include "sw/timing/spread.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

TEST(Quantile, InterpolatesBetweenOrderStatistics) {
    const std::vector<double> five = {10, 20, 30, 40, 50};
    EXPECT_DOUBLE_EQ(quantile(five, 0.0), 10);
    EXPECT_DOUBLE_EQ(quantile(five, 1.0), 50);
    EXPECT_DOUBLE_EQ(quantile(five, 0.5), 30);
    // h = 4 * 0.1 = 0.4: 10 + 0.4 * (20 - 10)
    EXPECT_DOUBLE_EQ(quantile(five, 0.1), 14);
    // h = 4 * 0.9 = 3.6: 40 + 0.6 * (50 - 40)
    EXPECT_DOUBLE_EQ(quantile(five, 0.9), 46);
}

TEST(Quantile, MedianOfAnEvenCountIsTheMeanOfTheMiddleTwo) {
    EXPECT_DOUBLE_EQ(quantile({1, 2, 4, 8}, 0.5), 3);
}

TEST(Quantile, MatchesNumPysDefaultOnElevenSamples) {
    // numpy.percentile(range(0, 110, 10), [10, 50, 90]) -> 10, 50, 90
    std::vector<double> eleven;
    for (int k = 0; k <= 10; ++k) eleven.push_back(10.0 * k);
    EXPECT_DOUBLE_EQ(quantile(eleven, 0.1), 10);
    EXPECT_DOUBLE_EQ(quantile(eleven, 0.5), 50);
    EXPECT_DOUBLE_EQ(quantile(eleven, 0.9), 90);
}

TEST(Quantile, OneSampleIsEveryQuantileAndNoneIsZero) {
    EXPECT_DOUBLE_EQ(quantile({7}, 0.1), 7);
    EXPECT_DOUBLE_EQ(quantile({7}, 0.9), 7);
    EXPECT_DOUBLE_EQ(quantile({}, 0.5), 0);
}

TEST(Spread, SortsItsSamplesAndCountsThem) {
    const Spread s = spread_of({50, 10, 40, 20, 30});
    EXPECT_DOUBLE_EQ(s.mean, 30);
    EXPECT_DOUBLE_EQ(s.p50, 30);
    // h = 4 * 0.99 = 3.96: 40 + 0.96 * (50 - 40)
    EXPECT_DOUBLE_EQ(s.p99, 49.6);
    EXPECT_DOUBLE_EQ(s.max, 50);
    EXPECT_EQ(s.count, 5u);
}

TEST(Spread, AnOutlierMovesTheMeanButNotTheMedian) {
    const Spread s = spread_of({100, 101, 99, 100, 5000});
    EXPECT_DOUBLE_EQ(s.p50, 100);
    EXPECT_DOUBLE_EQ(s.mean, 1080);
    EXPECT_DOUBLE_EQ(s.max, 5000);
}

TEST(Spread, ScalesEveryFigureButTheCount) {
    const Spread s = spread_of({1, 2, 3}).scaled(4);
    EXPECT_DOUBLE_EQ(s.mean, 8);
    EXPECT_DOUBLE_EQ(s.p50, 8);
    EXPECT_DOUBLE_EQ(s.p99, 11.92);
    EXPECT_DOUBLE_EQ(s.max, 12);
    EXPECT_EQ(s.count, 3u);
}

TEST(GeometricMean, WeighsEachValueTheSameWhateverItsMagnitude) {
    EXPECT_DOUBLE_EQ(geometric_mean({2, 8}), 4);
    EXPECT_NEAR(geometric_mean({10, 100, 1000}), 100, 1e-9);
    EXPECT_DOUBLE_EQ(geometric_mean({}), 0);
}

TEST(Spread, NoSamplesGiveZeros) {
    const Spread s = spread_of({});
    EXPECT_DOUBLE_EQ(s.mean, 0);
    EXPECT_DOUBLE_EQ(s.max, 0);
    EXPECT_EQ(s.count, 0u);
}

}  // namespace
}  // namespace cdvp
