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
    EXPECT_DOUBLE_EQ(s.median, 30);
    EXPECT_DOUBLE_EQ(s.p10, 14);
    EXPECT_DOUBLE_EQ(s.p90, 46);
    EXPECT_EQ(s.count, 5u);
}

TEST(Spread, AnOutlierMovesTheMedianLittle) {
    const Spread s = spread_of({100, 101, 99, 100, 5000});
    EXPECT_DOUBLE_EQ(s.median, 100);
    EXPECT_GT(s.p90, 101);
}

TEST(Spread, ScalesEveryFigureButTheCount) {
    const Spread s = spread_of({1, 2, 3}).scaled(4);
    EXPECT_DOUBLE_EQ(s.median, 8);
    EXPECT_DOUBLE_EQ(s.p10, 4.8);
    EXPECT_DOUBLE_EQ(s.p90, 11.2);
    EXPECT_EQ(s.count, 3u);
}

}  // namespace
}  // namespace cdvp
