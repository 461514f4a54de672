// When a timing is clean, how its quality reads on one line, and how two
// baselines' qualities combine; a frame timed again replaces its sample.
#include <gtest/gtest.h>

#include "sw/timing/frame_samples.h"
#include "sw/timing/timing_quality.h"

namespace cdvp {
namespace {

TimingQuality quality(uint64_t timed, uint64_t retimed, uint64_t never, uint32_t runs, double spread) {
    TimingQuality q;
    q.frames_timed = timed;
    q.frames_retimed = retimed;
    q.never_clean = never;
    q.frames_disturbed = retimed + never;
    q.runs = runs;
    q.repeat_spread = spread;
    q.load_start = {0.5, 0, 0};
    q.load_end = {1.25, 0, 0};
    return q;
}

TEST(TimingQuality, IsCleanWhenEveryFrameCameCleanAndTheRepeatsAgree) {
    EXPECT_TRUE(quality(28, 3, 0, 1, 0).clean());
    EXPECT_FALSE(quality(28, 0, 1, 1, 0).clean()) << "one frame never came clean";
    EXPECT_TRUE(quality(84, 0, 0, 3, kMaxRepeatSpread).clean());
    EXPECT_FALSE(quality(84, 0, 0, 3, kMaxRepeatSpread * 1.01).clean()) << "the repeats disagree";
    EXPECT_TRUE(quality(28, 0, 0, 1, 0.5).clean()) << "one run has no repeats to disagree";
}

TEST(TimingQuality, SaysOnOneLineWhatItRestsOn) {
    EXPECT_EQ(quality(28, 0, 0, 1, 0).describe(3), "clean (load 0.50 to 1.25)");
    EXPECT_EQ(quality(84, 2, 0, 3, 0.021).describe(3), "clean (2 of 84 frames re-timed, repeats 2.1% apart, load 0.50 to 1.25)");
    TimingQuality slowed = quality(28, 1, 2, 1, 0);
    slowed.frames_slowed = 3;
    EXPECT_EQ(slowed.describe(1), "disturbed: 2 of 28 frames never came clean after 1 try, 1 of 28 frames re-timed, 3 on a "
                                  "slowed CPU, load 0.50 to 1.25");
    EXPECT_EQ(quality(56, 0, 0, 2, 0.125).describe(3), "disturbed: repeats 12.5% apart (over 10%), load 0.50 to 1.25");
}

TEST(TimingQuality, TwoBaselinesAddTheirCountsAndKeepTheWorseSpread) {
    TimingQuality a = quality(28, 1, 0, 3, 0.02);
    a += quality(28, 2, 1, 3, 0.04);
    EXPECT_EQ(a.frames_timed, 56u);
    EXPECT_EQ(a.frames_retimed, 3u);
    EXPECT_EQ(a.never_clean, 1u);
    EXPECT_EQ(a.frames_disturbed, 4u);
    EXPECT_DOUBLE_EQ(a.repeat_spread, 0.04);
    EXPECT_DOUBLE_EQ(a.load_start[0], 0.5) << "the first's loads";
}

// A disturbed timing says in one line what would time it clean, by cause;
// a clean one says nothing.
TEST(TimingQuality, ADisturbedTimingSaysWhatWouldHelp) {
    TimingQuality q;
    q.frames_timed = 40;
    EXPECT_EQ(q.advice(3, false, 2), "");
    q.frames_disturbed = 6;
    q.frames_slowed = 2;
    q.never_clean = 3;
    q.load_end = {3.5, 2, 1};
    EXPECT_EQ(q.advice(3, false, 2),
              "to time it clean: a quieter machine (load 3.50 on 2 CPUs), --pin-cpu N, --retime-tries 6");
    q.load_end = {0.2, 0, 0};
    EXPECT_EQ(q.advice(4, true, 8),
              "to time it clean: a quieter machine (a neighbour or a lowered clock slowed the CPU), --retime-tries 8")
        << "pinned: no --pin-cpu; a quiet load: the slowed CPU said";
    q.frames_slowed = 6;  // every disturbed frame slowed: pinning would not help
    EXPECT_EQ(q.advice(3, false, 8).find("--pin-cpu"), std::string::npos);
    TimingQuality spread;
    spread.frames_timed = 40;
    spread.runs = 3;
    spread.repeat_spread = 0.2;
    EXPECT_EQ(spread.advice(3, true, 8), "to time it clean: --repeat 5 (the median run counts)");
}

TEST(RepeatSpread, IsMaxOverMinMinusOne) {
    EXPECT_DOUBLE_EQ(repeat_spread_of({}), 0);
    EXPECT_DOUBLE_EQ(repeat_spread_of({5}), 0);
    EXPECT_NEAR(repeat_spread_of({100, 110, 105}), 0.1, 1e-12);
}

TEST(FrameSamples, AFrameTimedAgainReplacesItsSampleInItsRun) {
    FrameSamples s(1);
    for (const double v : {50.0, 10.0, 30.0, 10.0}) s.add(v);
    s.start_run();
    for (const double v : {40.0, 10.0, 10.0, 10.0}) s.add(v);
    EXPECT_NEAR(s.figures().spread.mean, (50.0 / 3 + 10) / 2, 1e-12) << "the median of the runs' means, 50/3 and 10";
    s.replace(0, 2, 10);
    EXPECT_DOUBLE_EQ(s.figures().spread.mean, 10);
    s.replace(1, 0, 99);  // a warm-up frame: kept apart from the figures
    EXPECT_DOUBLE_EQ(s.figures().spread.mean, 10);
    s.replace(5, 0, 1);  // no such run: nothing
    s.replace(0, 9, 1);  // no such frame: nothing
    const std::vector<std::vector<double>> values = s.run_values();
    ASSERT_EQ(values.size(), 2u);
    EXPECT_EQ(values[0], (std::vector<double>{50, 10, 10, 10}));
    EXPECT_EQ(values[1], (std::vector<double>{99, 10, 10, 10}));
}

}  // namespace
}  // namespace cdvp
