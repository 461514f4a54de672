// PairMemo gives PairFinder's own answer: the same pairs in the same order for
// the same words and format, a fresh search for any other words or format, a
// budget refused as the finder refuses it, and no more memory than its bound.
#include "models/fast_engine/pair_memo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace cdvp {
namespace {

struct Words {
    std::vector<uint32_t> columns[kCoordinates];
    CoordinateWords view() const {
        CoordinateWords v{};
        for (uint32_t c = 0; c < kCoordinates; ++c) v[c] = columns[c].data();
        return v;
    }
};

// Boxes of side up to 1 in a cube of side cbrt(2n): about one pair a box.
Words scene(uint32_t n, uint32_t seed) {
    std::vector<FloatBox> boxes(n);
    std::mt19937 rng(seed);
    const float extent = std::cbrt(2.0f * static_cast<float>(n));
    std::uniform_real_distribution<float> corner(0, extent), side(0, 1);
    for (FloatBox& b : boxes) {
        for (int a = 0; a < 3; ++a) b.min[a] = corner(rng), b.max[a] = b.min[a] + side(rng);
    }
    Words w;
    float32_words(boxes, w.columns);
    return w;
}

TEST(PairMemo, AHitIsTheFindersAnswerAndOtherWordsSearchAgain) {
    PairMemo memo;
    PairFinder finder;
    const Words a = scene(600, 1), b = scene(600, 2);
    PairList expected_a, expected_b, got;
    PairFinder().find(600, a.view(), expected_a);
    PairFinder().find(600, b.view(), expected_b);
    ASSERT_NE(expected_a, expected_b);
    memo.find(finder, 600, a.view(), got);
    EXPECT_EQ(got, expected_a);
    memo.find(finder, 600, b.view(), got);
    EXPECT_EQ(got, expected_b);
    memo.find(finder, 600, a.view(), got);
    EXPECT_EQ(got, expected_a);
    EXPECT_EQ(memo.hits(), 1u);
    EXPECT_EQ(memo.misses(), 2u);
    // One word changed, and fewer boxes of the same words: each a search of its own.
    Words moved = a;
    moved.columns[3][599] ^= 1;
    PairList expected_moved;
    PairFinder().find(600, moved.view(), expected_moved);
    memo.find(finder, 600, moved.view(), got);
    EXPECT_EQ(got, expected_moved);
    PairList expected_fewer;
    PairFinder().find(300, a.view(), expected_fewer);
    memo.find(finder, 300, a.view(), got);
    EXPECT_EQ(got, expected_fewer);
    EXPECT_EQ(memo.hits(), 1u);
}

TEST(PairMemo, AnOrderIsAppliedOnceAndKeptUnderItsKey) {
    PairMemo memo;
    PairFinder finder;
    const Words a = scene(603, 7);  // not a multiple of the hash's eight words
    PairList found, got;
    PairFinder().find(603, a.view(), found);
    ASSERT_GT(found.size(), 10u);
    int reversals = 0, rotations = 0;
    const PairMemo::Order reversed{5, [&reversals](PairList& p) { ++reversals, std::reverse(p.begin(), p.end()); }};
    const PairMemo::Order rotated{6, [&rotations](PairList& p) { ++rotations, std::rotate(p.begin(), p.begin() + 1, p.end()); }};
    PairList expected_reversed(found.rbegin(), found.rend());
    PairList expected_rotated = found;
    std::rotate(expected_rotated.begin(), expected_rotated.begin() + 1, expected_rotated.end());

    memo.find(finder, 603, a.view(), got, &reversed);
    EXPECT_EQ(got, expected_reversed);
    memo.find(finder, 603, a.view(), got, &reversed);
    EXPECT_EQ(got, expected_reversed);
    memo.find(finder, 603, a.view(), got, &rotated);
    EXPECT_EQ(got, expected_rotated);
    memo.find(finder, 603, a.view(), got);  // no order: the finder's own
    EXPECT_EQ(got, found);
    memo.find(finder, 603, a.view(), got, &rotated);
    EXPECT_EQ(got, expected_rotated);
    EXPECT_EQ(reversals, 1);
    EXPECT_EQ(rotations, 1);
    EXPECT_EQ(memo.misses(), 1u);
    EXPECT_EQ(memo.hits(), 4u);
    // Each kept order counts against the bound.
    EXPECT_GE(memo.bytes(), 3 * found.size() * sizeof(IndexPair) + 6 * 603 * sizeof(uint32_t));
    // Without a memo, find_pairs applies the order itself.
    find_pairs(nullptr, finder, 603, a.view(), got, &reversed);
    EXPECT_EQ(got, expected_reversed);
    EXPECT_EQ(reversals, 2);
}

TEST(PairMemo, TheFormatIsPartOfTheKey) {
    PairMemo memo;
    const Words w = scene(400, 3);
    PairFinder float32, fixed8(NumberFormat::fixed(8));
    PairList from_float, from_fixed, expected_fixed;
    memo.find(float32, 400, w.view(), from_float);
    memo.find(fixed8, 400, w.view(), from_fixed);
    PairFinder(NumberFormat::fixed(8)).find(400, w.view(), expected_fixed);
    EXPECT_EQ(from_fixed, expected_fixed);
    EXPECT_EQ(memo.hits(), 0u) << "one entry a format";
    EXPECT_EQ(memo.misses(), 2u);
}

TEST(PairMemo, ABudgetIsRefusedAsTheFinderRefusesIt) {
    PairMemo memo;
    const Words w = scene(500, 4);
    PairList pairs;
    PairFinder unlimited;
    memo.find(unlimited, 500, w.view(), pairs);
    ASSERT_GT(pairs.size(), 10u);
    PairFinder tight(NumberFormat::float32(), PairBudget(10));
    EXPECT_THROW(memo.find(tight, 500, w.view(), pairs), PairBudgetExceeded);
}

TEST(PairMemo, StaysWithinItsBytesDroppingTheLeastRecentlyUsed) {
    const Words a = scene(1000, 5), b = scene(1000, 6);
    PairMemo memo(40000);  // one scene's words (24 KB) and pairs, not two
    PairFinder finder;
    PairList pairs;
    memo.find(finder, 1000, a.view(), pairs);
    memo.find(finder, 1000, b.view(), pairs);
    EXPECT_LE(memo.bytes(), 40000u);
    memo.find(finder, 1000, b.view(), pairs);
    EXPECT_EQ(memo.hits(), 1u);
    memo.find(finder, 1000, a.view(), pairs);  // dropped for b
    EXPECT_EQ(memo.hits(), 1u);
    EXPECT_EQ(memo.misses(), 3u);
    PairMemo none(10);  // smaller than any entry: keeps nothing, answers all the same
    PairList expected;
    PairFinder().find(1000, a.view(), expected);
    none.find(finder, 1000, a.view(), pairs);
    none.find(finder, 1000, a.view(), pairs);
    EXPECT_EQ(pairs, expected);
    EXPECT_EQ(none.bytes(), 0u);
    EXPECT_EQ(none.hits(), 0u);
}

}  // namespace
}  // namespace cdvp
