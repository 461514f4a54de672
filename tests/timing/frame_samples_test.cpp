#include "sw/timing/frame_samples.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

TEST(FrameSamples, LeavesTheWarmUpFramesOut) {
    FrameSamples samples(2);
    for (double v : {900.0, 300.0, 10.0, 20.0, 30.0}) samples.add(v);
    const TimingFigures f = samples.figures();
    EXPECT_DOUBLE_EQ(f.spread.median, 20);
    EXPECT_EQ(f.frames_per_run, 3u);
    EXPECT_EQ(f.spread.count, 3u);
    EXPECT_FALSE(f.includes_warmup);
}

TEST(FrameSamples, NoWarmUpMeasuresEveryFrame) {
    FrameSamples samples(0);
    for (double v : {900.0, 10.0, 20.0}) samples.add(v);
    EXPECT_DOUBLE_EQ(samples.figures().spread.median, 20);
    EXPECT_EQ(samples.figures().frames_per_run, 3u);
}

TEST(FrameSamples, ARunNoLongerThanItsWarmUpFallsBackOnTheWarmUpFrames) {
    FrameSamples samples(3);
    for (double v : {5.0, 7.0}) samples.add(v);
    const TimingFigures f = samples.figures();
    EXPECT_TRUE(f.includes_warmup);
    EXPECT_DOUBLE_EQ(f.spread.median, 6);
    EXPECT_EQ(f.frames_per_run, 2u);
    EXPECT_TRUE(f.too_few_frames());
}

TEST(FrameSamples, NoFramesGiveZerosAndNoRuns) {
    const TimingFigures f = FrameSamples(2).figures();
    EXPECT_EQ(f.frames_per_run, 0u);
    EXPECT_TRUE(f.run_medians.empty());
    EXPECT_DOUBLE_EQ(f.spread.median, 0);
    EXPECT_FALSE(f.includes_warmup);
}

TEST(FrameSamples, TheMedianOverRunsIsTheMedianOfEachRunsMedian) {
    FrameSamples samples(1);
    const std::vector<std::vector<double>> runs = {{99, 1, 2, 3}, {99, 10, 11, 12}, {99, 4, 5, 600}};
    for (const auto& run : runs) {
        samples.start_run();
        for (double v : run) samples.add(v);
    }
    const TimingFigures f = samples.figures();
    EXPECT_EQ(samples.runs(), 3u);
    EXPECT_EQ(f.run_medians, (std::vector<double>{2, 11, 5}));
    EXPECT_DOUBLE_EQ(f.spread.median, 5);
    EXPECT_EQ(f.frames_per_run, 3u);
    // p10 and p90 pool the nine measured frames: 1 2 3 4 5 10 11 12 600.
    EXPECT_DOUBLE_EQ(f.spread.p10, 1.8);
    EXPECT_DOUBLE_EQ(f.spread.p90, 129.6);
    EXPECT_EQ(f.spread.count, 9u);
}

TEST(FrameSamples, FlagsFiguresOnFewerThanTheMinimumFrames) {
    FrameSamples samples(0);
    for (uint64_t k = 0; k + 1 < kMinMeasuredFrames; ++k) samples.add(1.0);
    EXPECT_TRUE(samples.figures().too_few_frames());
    samples.add(1.0);
    EXPECT_FALSE(samples.figures().too_few_frames());
}

}  // namespace
}  // namespace cdvp
