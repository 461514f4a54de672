// Two box banks, without a kernel: the host writes one bank while the board
// sweeps the other, START hands the banks over, and the previous pair buffer
// keeps the last sweep's pairs readable (in every format) while the next
// one sweeps. One bank refuses the same writes, as the paper's board does.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "models/board/board_core.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/pair_collector/pair_format.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using R = ControlRegisters;
constexpr auto bank_register = testing::read_register;

BoardConfig two_banks(uint32_t buffer_depth = 1000) {
    BoardConfig config;
    config.m = 2;
    config.box_banks = 2;
    config.collector.buffer_depth = buffer_depth;
    return config;
}

void load(BoardCore& core, const std::vector<FloatBox>& boxes) {
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            const float v = c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3];
            ASSERT_EQ(RegisterResult::kDone, core.write_coordinate(static_cast<Coordinate>(c), i, ComparisonUnit::as_bits(v)))
                << "box " << i;
        }
    }
}

void start(BoardCore& core, uint32_t objects) {
    core.write_register(R::kObjectCount, objects);
    core.write_register(R::kControl, R::kStart);
}

void run_to_done(BoardCore& core) {
    while (core.running()) core.step();
    ASSERT_EQ(SweepState::kDone, core.phase());
}

PairList shown(BoardCore& core) {
    PairList pairs;
    for (uint32_t k = 0; k < core.buffered_pairs(); ++k) pairs.push_back(core.buffered_pair(k));
    return pairs;
}

TEST(BoxBanks, TheRegistersSayHowManyBanksAndWhichTheHostWrites) {
    BoardCore one(BoardConfig{}, 64), two(two_banks(), 64);
    EXPECT_EQ(1u, bank_register(one, R::kBoxBanks));
    EXPECT_EQ(2u, bank_register(two, R::kBoxBanks));
    EXPECT_EQ(0u, bank_register(two, R::kHostBank));
    BoardConfig single = two_banks();
    single.box_banks = 1;
    EXPECT_EQ(2 * single.block_rams(500), two_banks().block_rams(500)) << "a second bank doubles the box memory";
    BoardConfig three = two_banks();
    three.box_banks = 3;
    EXPECT_THROW(three.validate(), std::invalid_argument);
}

TEST(BoxBanks, TheHostWritesTheOtherBankWhileASweepRuns) {
    std::mt19937 rng(7);
    const std::vector<FloatBox> first = testing::random_boxes(40, 4.0f, 1.5f, rng);
    const std::vector<FloatBox> second = testing::random_boxes(40, 4.0f, 1.5f, rng);
    BoardCore core(two_banks(), 64);
    load(core, first);
    start(core, 40);
    ASSERT_TRUE(core.running());
    EXPECT_EQ(1u, bank_register(core, R::kHostBank)) << "START hands bank 0 to the sweep";
    load(core, second);  // into bank 1 while bank 0 sweeps
    EXPECT_FALSE(core.status().error);
    run_to_done(core);

    // The sweep saw the first boxes only: the same pairs as a board that never saw the second.
    BoardConfig reference_config = two_banks();
    reference_config.box_banks = 1;
    BoardCore reference(reference_config, 64);
    const testing::CoreRun expected_first = testing::run_core(reference, first);
    EXPECT_EQ(expected_first.pairs, shown(core));
    BoardCore reference2(reference_config, 64);
    const testing::CoreRun expected_second = testing::run_core(reference2, second);

    start(core, 40);  // sweeps bank 1: the second boxes
    EXPECT_EQ(0u, bank_register(core, R::kHostBank));
    core.write_register(R::kPairBank, R::kPreviousPairs);
    EXPECT_EQ(expected_first.pairs, shown(core)) << "the first sweep's pairs, readable during the second";
    EXPECT_EQ(expected_first.pairs.size(), bank_register(core, R::kPairCount));
    run_to_done(core);
    EXPECT_EQ(expected_first.pairs, shown(core)) << "until the next START";
    core.write_register(R::kPairBank, R::kCurrentPairs);
    EXPECT_EQ(expected_second.pairs, shown(core));
    EXPECT_NE(expected_first.pairs, expected_second.pairs) << "scenes that tell the banks apart";
}

TEST(BoxBanks, OneBankRefusesWritesDuringASweepAsThePapersBoardDoes) {
    std::mt19937 rng(8);
    BoardConfig config = two_banks();
    config.box_banks = 1;
    BoardCore core(config, 64);
    load(core, testing::random_boxes(40, 4.0f, 1.5f, rng));
    start(core, 40);
    EXPECT_EQ(0u, bank_register(core, R::kHostBank));
    EXPECT_EQ(RegisterResult::kRefused, core.write_coordinate(kMinX, 3, 0));
    EXPECT_EQ(uint32_t{R::kWriteWhileBusy}, bank_register(core, R::kErrorCause));
}

TEST(BoxBanks, ABadPairBankIsRefusedWithItsCause) {
    BoardCore core(two_banks(), 16);
    EXPECT_EQ(RegisterResult::kRefused, core.write_register(R::kPairBank, 2));
    EXPECT_EQ(uint32_t{R::kBadPairBank}, bank_register(core, R::kErrorCause));
    EXPECT_EQ(uint32_t{R::kCurrentPairs}, bank_register(core, R::kPairBank));
}

// The previous buffer reads in PAIR_FORMAT too, encoded over its own sweep's boxes.
TEST(BoxBanks, ThePreviousPairsReadInEveryFormat) {
    std::mt19937 rng(9);
    const std::vector<FloatBox> first = testing::random_boxes(60, 4.0f, 1.5f, rng);
    const std::vector<FloatBox> second = testing::random_boxes(20, 4.0f, 1.5f, rng);
    for (const PairFormat format : {PairFormat::kList, PairFormat::kCounted, PairFormat::kBitmap}) {
        BoardCore core(two_banks(), 64);
        core.write_register(R::kPairFormat, static_cast<uint32_t>(format));
        load(core, first);
        start(core, 60);
        run_to_done(core);
        const PairList expected = shown(core);
        ASSERT_FALSE(expected.empty());
        load(core, second);
        start(core, 20);
        core.write_register(R::kPairBank, R::kPreviousPairs);
        std::vector<uint32_t> words(core.window_words());
        core.copy_window_words(0, words.size(), reinterpret_cast<unsigned char*>(words.data()));
        EXPECT_EQ(words.size(), bank_register(core, R::kPairWords));
        PairList decoded;
        if (format == PairFormat::kList) {
            for (std::size_t k = 0; k + 1 < words.size(); k += 2) decoded.push_back({words[k], words[k + 1]});
        } else {
            ASSERT_EQ("", decode_pairs(format, words.data(), words.size(), 60, decoded)) << static_cast<int>(format);
        }
        EXPECT_EQ(sorted(expected), sorted(decoded)) << static_cast<int>(format);
    }
}

}  // namespace
}  // namespace cdvp
