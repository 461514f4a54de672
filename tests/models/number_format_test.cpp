#include "models/number_format/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "models/board_spec/board_config.h"
#include "models/comparison_unit/comparison_unit.h"

namespace cdvp {
namespace {

uint32_t bits_of(float value) { return ComparisonUnit::as_bits(value); }

TEST(NumberFormat, ParsesFloat32AndFixed8To32AndNamesThem) {
    EXPECT_TRUE(NumberFormat::parse("float32").is_float());
    EXPECT_EQ(NumberFormat().name(), "float32");
    for (uint32_t k = 8; k <= 32; ++k) {
        const NumberFormat f = NumberFormat::parse("fixed" + std::to_string(k));
        EXPECT_FALSE(f.is_float());
        EXPECT_EQ(f.bits(), k);
        EXPECT_EQ(f.name(), "fixed" + std::to_string(k));
        EXPECT_EQ(NumberFormat::from_register(f.register_value()), f);
    }
    EXPECT_EQ(NumberFormat::float32().register_value(), 0u);
}

TEST(NumberFormat, RefusesOtherNamesWithTheExpectedValues) {
    for (const char* bad : {"fixed7", "fixed33", "int16", "fixed", "fixed08", "fixed16 ", "Float32", "", "fixed-8",
                            "fixed100"}) {
        try {
            NumberFormat::parse(bad);
            ADD_FAILURE() << bad << " accepted";
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("expected float32 or fixedK with K from 8 to 32"), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
    EXPECT_THROW(NumberFormat::fixed(7), std::invalid_argument);
    EXPECT_THROW(NumberFormat::fixed(33), std::invalid_argument);
    EXPECT_THROW(NumberFormat::from_register(7), std::invalid_argument);
    EXPECT_THROW(NumberFormat::from_register(33), std::invalid_argument);
}

TEST(NumberFormat, WordMaskKeepsTheLowKBits) {
    EXPECT_EQ(NumberFormat::float32().word_mask(), 0xFFFF'FFFFu);
    EXPECT_EQ(NumberFormat::fixed(8).word_mask(), 0xFFu);
    EXPECT_EQ(NumberFormat::fixed(18).word_mask(), 0x3'FFFFu);
    EXPECT_EQ(NumberFormat::fixed(31).word_mask(), 0x7FFF'FFFFu);
    EXPECT_EQ(NumberFormat::fixed(32).word_mask(), 0xFFFF'FFFFu);
}

// The layout with the fewest 18-Kbit primitives: a deeper aspect, or several
// coordinates of a box side by side in one word.
TEST(NumberFormat, BlockRamLayoutTakesTheFewestPrimitives) {
    auto primitives = [](NumberFormat f, uint64_t boxes) { return f.block_ram_layout(boxes).primitives(boxes); };
    const NumberFormat float32 = NumberFormat::float32();
    EXPECT_EQ(float32.block_ram_layout(100).width, 36u);
    EXPECT_EQ(float32.block_ram_layout(100).coordinates_per_word, 1u);
    EXPECT_EQ(primitives(float32, 512), 6u);
    EXPECT_EQ(primitives(float32, 513), 12u);
    EXPECT_EQ(primitives(NumberFormat::fixed(19), 1024), 12u);  // only 512 x 36 holds 19 bits
    // fixed16: min and max of an axis share a 36-bit word.
    EXPECT_EQ(NumberFormat::fixed(16).block_ram_layout(512).coordinates_per_word, 2u);
    EXPECT_EQ(primitives(NumberFormat::fixed(16), 512), 3u);
    EXPECT_EQ(primitives(NumberFormat::fixed(16), 2048), 12u);  // 3 x 4 = 6 x 2 (1K x 18)
    EXPECT_EQ(primitives(NumberFormat::fixed(18), 512), 3u);
    // fixed12: three a word, at any depth better than 1K x 18.
    EXPECT_EQ(primitives(NumberFormat::fixed(12), 1024), 4u);
    EXPECT_EQ(primitives(NumberFormat::fixed(12), 2048), 8u);
    // fixed8: four a 36-bit word for a small tile, 2K x 9 or 1K x 18 (two a word) for more.
    EXPECT_EQ(primitives(NumberFormat::fixed(8), 512), 2u);
    EXPECT_EQ(primitives(NumberFormat::fixed(8), 2048), 6u);
    EXPECT_EQ(NumberFormat::fixed(9).block_ram_layout(2049).width, 18u);
    EXPECT_EQ(primitives(NumberFormat::fixed(9), 2049), 9u);
    EXPECT_EQ(primitives(NumberFormat::fixed(8), 0), 0u);
    BoardConfig board;
    board.m = 4;
    EXPECT_EQ(board.block_rams(2048), 4u * 24);
    board.format = NumberFormat::fixed(16);
    EXPECT_EQ(board.block_rams(2048), 4u * 12);
    EXPECT_EQ(board.block_rams(500), 4u * 3);
    board.format = NumberFormat::fixed(9);
    EXPECT_EQ(board.block_rams(2048), 4u * 6);
    EXPECT_EQ(board.block_rams(2049), 4u * 9);
}

TEST(NumberFormat, Float32ComparesAsIeeeAndKeysKeepThatOrder) {
    const NumberFormat f = NumberFormat::float32();
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = INFINITY;
    EXPECT_TRUE(f.less_equal(bits_of(-0.0f), bits_of(0.0f)));
    EXPECT_TRUE(f.less_equal(bits_of(0.0f), bits_of(-0.0f)));
    EXPECT_EQ(f.key(bits_of(-0.0f)), f.key(bits_of(0.0f)));
    EXPECT_FALSE(f.less_equal(bits_of(nan), bits_of(inf)));
    EXPECT_FALSE(f.less_equal(bits_of(-inf), bits_of(nan)));
    EXPECT_TRUE(f.excluded(bits_of(nan)));
    EXPECT_TRUE(f.excluded(bits_of(-nan)));
    EXPECT_FALSE(f.excluded(bits_of(inf)));
    EXPECT_FALSE(f.excluded(bits_of(-inf)));
    std::mt19937 random(9);
    const float specials[] = {0.0f, -0.0f, inf, -inf, 1e-45f, -1e-45f, 1.17e-38f, 3.4e38f, -3.4e38f, 1.0f, -1.0f};
    std::vector<uint32_t> words;
    for (float v : specials) words.push_back(bits_of(v));
    for (int k = 0; k < 200; ++k) words.push_back(random());
    for (uint32_t a : words) {
        for (uint32_t b : words) {
            if (f.excluded(a) || f.excluded(b)) continue;
            EXPECT_EQ(f.key(a) <= f.key(b), f.less_equal(a, b)) << std::hex << a << " " << b;
            if (f.key(a) <= f.key(b)) {
                EXPECT_LE(f.approximate(f.key(a)), f.approximate(f.key(b)));
            }
        }
    }
}

TEST(NumberFormat, FixedComparesTheLowBitsUnsigned) {
    for (uint32_t k : {8u, 16u, 31u, 32u}) {
        const NumberFormat f = NumberFormat::fixed(k);
        const uint32_t top = f.word_mask();
        EXPECT_TRUE(f.less_equal(0, top));
        EXPECT_FALSE(f.less_equal(top, 0));
        EXPECT_FALSE(f.excluded(bits_of(std::numeric_limits<float>::quiet_NaN())));
        // Bits above K are not stored: they never change a comparison.
        if (k < 32) {
            EXPECT_TRUE(f.less_equal(top + 1, 0)) << k;  // top + 1 keeps nothing
        }
        std::mt19937 random(k);
        for (int n = 0; n < 2000; ++n) {
            const uint32_t a = random(), b = random();
            EXPECT_EQ(f.key(a) <= f.key(b), f.less_equal(a, b));
            EXPECT_EQ(f.less_equal(a, b), (a & top) <= (b & top));
            if (f.key(a) <= f.key(b)) {
                EXPECT_LE(f.approximate(f.key(a)), f.approximate(f.key(b)));
            }
        }
    }
}

}  // namespace
}  // namespace cdvp
