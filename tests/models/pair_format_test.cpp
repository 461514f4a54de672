// The pair buffer's read-back formats: every format decodes to the pairs it
// encoded (sorted by row for the bitmap), takes the words its comment says,
// stays within its worst case, and a decoder refuses words no board sends.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "models/pair_collector/pair_format.h"

namespace cdvp {
namespace {

constexpr PairFormat kFormats[] = {PairFormat::kList, PairFormat::kCounted, PairFormat::kBitmap};

// Pairs as a sweep emits them: rows ascending, partners ascending within a row.
PairList sweep_pairs(uint32_t objects, double density, std::mt19937& rng) {
    std::bernoulli_distribution hit(density);
    PairList pairs;
    for (uint32_t i = 0; i < objects; ++i) {
        for (uint32_t j = i + 1; j < objects; ++j) {
            if (hit(rng)) pairs.push_back({i, j});
        }
    }
    return pairs;
}

TEST(PairFormat, EveryFormatDecodesToThePairsItEncoded) {
    std::mt19937 rng(5);
    for (uint32_t objects : {2u, 31u, 32u, 33u, 97u, 300u}) {
        for (double density : {0.0, 0.003, 0.05, 0.6}) {
            const PairList pairs = sweep_pairs(objects, density, rng);
            for (PairFormat format : kFormats) {
                std::vector<uint32_t> words;
                encode_pairs(format, pairs.data(), pairs.size(), objects, words);
                EXPECT_EQ(words.size(), encoded_words(format, pairs.data(), pairs.size(), objects));
                EXPECT_LE(words.size(), worst_encoded_words(format, pairs.size(), objects));
                PairList decoded;
                ASSERT_EQ("", decode_pairs(format, words.data(), words.size(), objects, decoded));
                EXPECT_EQ(pairs, decoded) << "format " << int(format) << ", " << objects << " boxes";
            }
        }
    }
}

// A tiled board emits a row's pairs in pieces and rows out of order: the
// counted format repeats the row, the bitmap returns them sorted.
TEST(PairFormat, TiledOrderKeepsEveryPair) {
    const PairList tiled = {{4, 9}, {4, 10}, {1, 9}, {4, 2000}, {1, 1999}, {1, 1500}, {0, 3}};
    for (PairFormat format : kFormats) {
        std::vector<uint32_t> words;
        encode_pairs(format, tiled.data(), tiled.size(), 2001, words);
        PairList decoded;
        ASSERT_EQ("", decode_pairs(format, words.data(), words.size(), 2001, decoded));
        PairList expected = tiled;
        if (format == PairFormat::kBitmap) std::sort(expected.begin(), expected.end());
        EXPECT_EQ(expected, decoded) << int(format);
    }
    // Runs: (4: 2), (1: 1), (4: 1), (1: 2), (0: 1).
    EXPECT_EQ(2u * 5 + 7, encoded_words(PairFormat::kCounted, tiled.data(), tiled.size(), 2001));
    // Rows 0 to 4 of ceil(2001 / 32) = 63 words, after the two header words.
    EXPECT_EQ(2u + 5 * 63, encoded_words(PairFormat::kBitmap, tiled.data(), tiled.size(), 2001));
}

TEST(PairFormat, SizesAsDocumented) {
    const PairList pairs = {{0, 1}, {0, 2}, {0, 3}, {5, 6}};
    EXPECT_EQ(8u, encoded_words(PairFormat::kList, pairs.data(), 4, 64));
    EXPECT_EQ(2u * 2 + 4, encoded_words(PairFormat::kCounted, pairs.data(), 4, 64));
    EXPECT_EQ(2u + 6 * 2, encoded_words(PairFormat::kBitmap, pairs.data(), 4, 64));
    for (PairFormat format : kFormats) EXPECT_EQ(0u, encoded_words(format, pairs.data(), 0, 64));
    EXPECT_EQ(3u * 10, worst_encoded_words(PairFormat::kCounted, 10, 64));
    EXPECT_EQ(2u + 100 * 4, worst_encoded_words(PairFormat::kBitmap, 10, 100));
}

TEST(PairFormat, WordsNoBoardSendsAreRefused) {
    PairList out;
    const std::vector<uint32_t> odd = {0, 1, 2};
    EXPECT_NE("", decode_pairs(PairFormat::kList, odd.data(), odd.size(), 10, out));
    const std::vector<uint32_t> backwards = {5, 2};
    EXPECT_NE("", decode_pairs(PairFormat::kList, backwards.data(), 2, 10, out));
    const std::vector<uint32_t> past = {1, 10};
    EXPECT_NE("", decode_pairs(PairFormat::kList, past.data(), 2, 10, out));
    const std::vector<uint32_t> long_run = {1, 3, 2, 3};  // three partners promised, two sent
    EXPECT_NE("", decode_pairs(PairFormat::kCounted, long_run.data(), long_run.size(), 10, out));
    const std::vector<uint32_t> empty_run = {1, 0};
    EXPECT_NE("", decode_pairs(PairFormat::kCounted, empty_run.data(), 2, 10, out));
    const std::vector<uint32_t> cut = {1, 1, 2, 4};  // a header cut after its row
    EXPECT_NE("", decode_pairs(PairFormat::kCounted, cut.data(), cut.size(), 10, out));
    const std::vector<uint32_t> short_map = {0, 2, 0xFF};  // two rows promised, one sent
    EXPECT_NE("", decode_pairs(PairFormat::kBitmap, short_map.data(), short_map.size(), 10, out));
    const std::vector<uint32_t> diagonal = {3, 1, 1u << 3};  // pair (3, 3)
    EXPECT_NE("", decode_pairs(PairFormat::kBitmap, diagonal.data(), diagonal.size(), 10, out));
    const std::vector<uint32_t> beyond = {0, 1, 1u << 12};  // box 12 of 10
    EXPECT_NE("", decode_pairs(PairFormat::kBitmap, beyond.data(), beyond.size(), 10, out));
}

}  // namespace
}  // namespace cdvp
