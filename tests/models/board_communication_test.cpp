// The board's side of the communication strategies, without a kernel: the
// delta stream writes whole records however the bursts split them and
// refuses what would leave the memories unknown; the pair window reads the
// buffer in PAIR_FORMAT, on both engines, pause by pause.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "models/board/board_core.h"
#include "models/comparison_unit/comparison_unit.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using R = ControlRegisters;
constexpr auto reg = testing::read_register;

std::vector<uint32_t> record(uint32_t index, uint32_t base) {
    std::vector<uint32_t> words{index};
    for (uint32_t c = 0; c < kCoordinates; ++c) words.push_back(base + c);
    return words;
}

RegisterResult stream(BoardCore& core, const std::vector<uint32_t>& words, std::size_t from, std::size_t count) {
    return core.write_delta(reinterpret_cast<const unsigned char*>(words.data() + from), static_cast<uint32_t>(count));
}

TEST(DeltaStream, RecordsSplitAcrossBurstsLandWhole) {
    BoardCore core(BoardConfig{}, 16);
    std::vector<uint32_t> words;
    for (uint32_t index : {3u, 15u, 0u}) {
        const std::vector<uint32_t> r = record(index, 100 * (index + 1));
        words.insert(words.end(), r.begin(), r.end());
    }
    // Bursts of 5, 1 and the rest: records cut at words 5 and 6.
    ASSERT_EQ(RegisterResult::kDone, stream(core, words, 0, 5));
    EXPECT_EQ(0u, core.read_coordinate(kMinX, 3)) << "a record is written only when whole";
    ASSERT_EQ(RegisterResult::kDone, stream(core, words, 5, 1));
    ASSERT_EQ(RegisterResult::kDone, stream(core, words, 6, words.size() - 6));
    for (uint32_t index : {3u, 15u, 0u}) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            EXPECT_EQ(100 * (index + 1) + c, core.read_coordinate(static_cast<Coordinate>(c), index)) << index;
        }
    }
    EXPECT_EQ(0u, core.read_coordinate(kMinX, 4)) << "boxes without a record keep their words";
    EXPECT_EQ(3u, reg(core, R::kDeltaRecords));
    EXPECT_FALSE(core.status().error);
}

TEST(DeltaStream, AnIndexPastTheCapacityIsAnErrorAndWritesNothing) {
    BoardCore core(BoardConfig{}, 16);
    ASSERT_EQ(RegisterResult::kDone, stream(core, record(16, 7), 0, 7));
    EXPECT_TRUE(core.status().error);
    EXPECT_EQ(R::kDeltaIndex, core.status().error_cause);
    EXPECT_EQ(0u, reg(core, R::kDeltaRecords));
    EXPECT_TRUE(core.interrupt());
}

TEST(DeltaStream, StartWithAPartRecordIsRefusedAndAbortDropsIt) {
    BoardCore core(BoardConfig{}, 16);
    ASSERT_EQ(RegisterResult::kDone, stream(core, record(2, 9), 0, 4));
    core.write_register(R::kObjectCount, 4);
    core.write_register(R::kControl, R::kStart);
    EXPECT_FALSE(core.running());
    EXPECT_EQ(R::kDeltaIncomplete, core.status().error_cause);
    core.write_register(R::kControl, R::kAbort);
    core.write_register(R::kControl, R::kStart);
    EXPECT_TRUE(core.running()) << "after ABORT the stream starts at a record's first word";
    EXPECT_EQ(RegisterResult::kRefused, stream(core, record(2, 9), 0, 7)) << "no writes during a sweep";
    EXPECT_EQ(R::kWriteWhileBusy, core.status().error_cause);
}

TEST(PairWindow, AnUnknownFormatOrAChangeDuringASweepIsRefused) {
    BoardCore core(BoardConfig{}, 16);
    EXPECT_EQ(RegisterResult::kRefused, core.write_register(R::kPairFormat, kPairFormats));
    EXPECT_EQ(R::kBadPairFormat, core.status().error_cause);
    EXPECT_EQ(0u, reg(core, R::kPairFormat));
    core.write_register(R::kControl, R::kAbort);
    ASSERT_EQ(RegisterResult::kDone, core.write_register(R::kPairFormat, 2));
    EXPECT_EQ(2u, reg(core, R::kPairFormat));
}

// A bitmap's rows are as wide as the sweep: past 11,584 boxes a full one
// outgrows the 16 MiB window, and START says so before any sweep.
TEST(PairWindow, ABitmapTooWideForTheWindowIsRefusedAtStart) {
    BoardCore core(BoardConfig{}, 11585);
    core.write_register(R::kPairFormat, static_cast<uint32_t>(PairFormat::kBitmap));
    core.write_register(R::kObjectCount, 11585);
    core.write_register(R::kControl, R::kStart);
    EXPECT_FALSE(core.running());
    EXPECT_EQ(R::kPairWindowFull, core.status().error_cause);
    core.write_register(R::kControl, R::kAbort);
    core.write_register(R::kObjectCount, 11584);
    core.write_register(R::kControl, R::kStart);
    EXPECT_TRUE(core.running());
}

// Every format reads each segment's pairs back, pause by pause, on both
// engines; the words are PAIR_WORDS and decode to the buffer.
TEST(PairWindow, EveryFormatReadsEachSegmentOnBothEngines) {
    std::mt19937 rng(41);
    const auto boxes = testing::random_boxes(150, 8.0f, 3.0f, rng);
    for (Fidelity fidelity : {Fidelity::kCycle, Fidelity::kFast}) {
        for (uint32_t f = 0; f < kPairFormats; ++f) {
            const auto format = static_cast<PairFormat>(f);
            BoardConfig config;
            config.m = 3;
            config.collector.buffer_depth = 40;
            BoardCore core(config, 150, fidelity);
            core.write_register(R::kPairFormat, f);
            BoardCore reference(config, 150, fidelity);
            const testing::CoreRun expected = testing::run_core(reference, boxes);
            ASSERT_GT(expected.pauses, 3u);
            for (uint32_t i = 0; i < boxes.size(); ++i) {
                for (uint32_t c = 0; c < kCoordinates; ++c) {
                    const float v = c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3];
                    core.write_coordinate(static_cast<Coordinate>(c), i, ComparisonUnit::as_bits(v));
                }
            }
            core.write_register(R::kObjectCount, 150);
            core.write_register(R::kControl, R::kStart);
            PairList got;
            for (;;) {
                core.advance_to(core.segment_edges());
                const uint64_t words = reg(core, R::kPairWords);
                std::vector<uint32_t> data(words);
                core.copy_window_words(0, words, reinterpret_cast<unsigned char*>(data.data()));
                PairList segment;
                ASSERT_EQ("", decode_pairs(format, data.data(), words, 150, segment));
                ASSERT_EQ(segment.size(), core.buffered_pairs());
                got.insert(got.end(), segment.begin(), segment.end());
                if (core.phase() == SweepState::kDone) break;
                core.write_register(R::kControl, R::kResume);
            }
            PairList want = expected.pairs;
            std::sort(want.begin(), want.end());
            std::sort(got.begin(), got.end());
            EXPECT_EQ(want, got) << to_string(fidelity) << ", format " << f;
        }
    }
}

}  // namespace
}  // namespace cdvp
