#include "sw/timing/frame_samples.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

TEST(FrameSamples, LeavesTheWarmUpFramesOut) {
    FrameSamples samples(2);
    for (double v : {900.0, 300.0, 10.0, 20.0, 30.0}) samples.add(v);
    const TimingFigures f = samples.figures();
    EXPECT_DOUBLE_EQ(f.spread.mean, 20);
    EXPECT_DOUBLE_EQ(f.spread.max, 30);
    EXPECT_EQ(f.frames_per_run, 3u);
    EXPECT_EQ(f.spread.count, 3u);
    EXPECT_FALSE(f.includes_warmup);
}

TEST(FrameSamples, NoWarmUpMeasuresEveryFrame) {
    FrameSamples samples(0);
    for (double v : {900.0, 10.0, 20.0}) samples.add(v);
    EXPECT_DOUBLE_EQ(samples.figures().spread.mean, 310);
    EXPECT_EQ(samples.figures().frames_per_run, 3u);
}

TEST(FrameSamples, ARunNoLongerThanItsWarmUpFallsBackOnTheWarmUpFrames) {
    FrameSamples samples(3);
    for (double v : {5.0, 7.0}) samples.add(v);
    const TimingFigures f = samples.figures();
    EXPECT_TRUE(f.includes_warmup);
    EXPECT_DOUBLE_EQ(f.spread.mean, 6);
    EXPECT_EQ(f.frames_per_run, 2u);
    EXPECT_TRUE(f.too_few_frames());
}

TEST(FrameSamples, NoFramesGiveZerosAndNoRuns) {
    const TimingFigures f = FrameSamples(2).figures();
    EXPECT_EQ(f.frames_per_run, 0u);
    EXPECT_TRUE(f.run_means.empty());
    EXPECT_DOUBLE_EQ(f.spread.mean, 0);
    EXPECT_FALSE(f.includes_warmup);
}

TEST(FrameSamples, RepeatsCombineByTheMedianOfEachRunsMean) {
    FrameSamples samples(1);
    const std::vector<std::vector<double>> runs = {{99, 1, 2, 3}, {99, 10, 11, 12}, {99, 4, 5, 600}};
    for (const auto& run : runs) {
        samples.start_run();
        for (double v : run) samples.add(v);
    }
    const TimingFigures f = samples.figures();
    EXPECT_EQ(samples.runs(), 3u);
    // Run means 2, 11 and 203, in the order the runs were timed; their median
    // is 11, where the mean over all nine frames (72) would follow the one
    // disturbed run.
    EXPECT_EQ(f.run_means, (std::vector<double>{2, 11, 203}));
    EXPECT_DOUBLE_EQ(f.spread.mean, 11);
    EXPECT_EQ(f.frames_per_run, 3u);
    // p50, p99 and max pool the nine measured frames: 1 2 3 4 5 10 11 12 600.
    EXPECT_DOUBLE_EQ(f.spread.p50, 5);
    EXPECT_DOUBLE_EQ(f.spread.p99, 12 + 0.92 * (600 - 12));
    EXPECT_DOUBLE_EQ(f.spread.max, 600);
    EXPECT_EQ(f.spread.count, 9u);
}

// A bimodal cost such as dbvt's: cheap on most frames, a rebuild every third.
// Its median is the cheap level whatever the rebuilds cost; its mean is what
// a simulation pays, and the speedup follows it.
TEST(FrameSamples, ABimodalSeriesIsReportedByItsMeanAndTheSpeedupFollowsIt) {
    FrameSamples software(0), board(0);
    for (int frame = 0; frame < 30; ++frame) {
        software.add(frame % 3 == 2 ? 10'000.0 : 400.0);
        board.add(2'000.0);
    }
    const TimingFigures sw = software.figures(), b = board.figures();
    EXPECT_DOUBLE_EQ(sw.spread.p50, 400);
    EXPECT_DOUBLE_EQ(sw.spread.mean, (20 * 400.0 + 10 * 10'000.0) / 30);  // 3600
    EXPECT_DOUBLE_EQ(sw.spread.max, 10'000);
    // By medians the board would lose (0.2x); by what the frames cost in all it wins 1.8x.
    EXPECT_LT(sw.spread.p50 / b.spread.mean, 1.0);
    EXPECT_DOUBLE_EQ(speedup(sw.spread, b.spread), 1.8);
    EXPECT_DOUBLE_EQ(speedup(sw.spread.scaled(4), b.spread), 7.2);
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
