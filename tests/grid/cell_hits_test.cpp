// Every compare width of the cell's lane tests against the comparators and
// the one-cell rule written out box by box.
#include "models/grid_fast_engine/cell_hits.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace cdvp {
namespace {

// Bit c of row r: c > r, on every axis r or c starts in the cell, and the
// six comparators hit.
uint64_t expected_row(const BoxColumns& columns, uint32_t n, const uint64_t (&starts)[3], uint32_t r) {
    uint64_t bits = 0;
    for (uint32_t c = r + 1; c < n; ++c) {
        bool keep = true;
        for (uint32_t a = 0; a < 3; ++a) keep &= ((starts[a] >> r | starts[a] >> c) & 1) != 0;
        int32_t row[kCoordinates], column[kCoordinates];
        columns.get(r, row);
        columns.get(c, column);
        if (keep && ComparisonUnit::lane_hit(row, column)) bits |= uint64_t{1} << c;
    }
    return bits;
}

TEST(CellHits, EveryWidthGivesTheComparatorsHitsUnderTheOneCellRule) {
    std::mt19937 random(35);
    const auto widths = cell_hits_widths();
    ASSERT_EQ(4u, widths.front().columns);
    uint32_t ran = 0;
    for (uint32_t n = 2; n <= 64; ++n) {
        for (int scene = 0; scene < 20; ++scene) {
            BoxColumns columns;
            columns.resize(n + kCellHitsPadding);
            // Keys near each other (many hits, equal bounds too), some
            // around the sign flip, and stale boxes past n that must not count.
            std::uniform_int_distribution<int32_t> start(-20, 20), size(0, 12);
            for (uint32_t k = 0; k < n + kCellHitsPadding; ++k) {
                const int32_t bias = scene % 2 == 0 ? 0 : INT32_MIN / 2;
                for (uint32_t a = 0; a < 3; ++a) {
                    const int32_t lo = bias + start(random);
                    columns.bound[a][k] = lo;
                    columns.bound[a + 3][k] = scene % 5 == 4 && k % 7 == 0 ? lo - 1 : lo + size(random);
                }
            }
            uint64_t starts[3];
            for (uint64_t& s : starts) s = (uint64_t{random()} << 32 | random()) | (scene % 3 == 0 ? ~uint64_t{0} : 0);
            for (const CellHitsWidth& width : widths) {
                if (!width.runs) continue;
                ++ran;
                std::vector<uint64_t> hits(n, ~uint64_t{0});
                width.hits(columns, n, starts, hits.data());
                for (uint32_t r = 0; r + 1 < n; ++r) {
                    ASSERT_EQ(expected_row(columns, n, starts, r), hits[r])
                        << width.columns << " columns a compare, n=" << n << " scene " << scene << " row " << r;
                }
            }
        }
    }
    EXPECT_GE(ran, 63u * 20u);
}

TEST(CellHits, TheChosenWidthAgreesWithTheNarrowest) {
    BoxColumns columns;
    columns.resize(64 + kCellHitsPadding);
    for (uint32_t k = 0; k < 64; ++k) {
        for (uint32_t a = 0; a < 3; ++a) {
            columns.bound[a][k] = static_cast<int32_t>(k % 9);
            columns.bound[a + 3][k] = static_cast<int32_t>(k % 9 + k % 4);
        }
    }
    const uint64_t starts[3] = {0x5555'5555'5555'5555u, ~uint64_t{0}, 0xF0F0'F0F0'F0F0'F0F0u};
    std::vector<uint64_t> chosen(64), narrowest(64);
    masked_cell_hits(columns, 64, starts, chosen.data());
    cell_hits_widths().front().hits(columns, 64, starts, narrowest.data());
    chosen.pop_back();
    narrowest.pop_back();
    EXPECT_EQ(narrowest, chosen);
    uint64_t any = 0;
    for (uint64_t row : chosen) any |= row;
    EXPECT_NE(0u, any);
}

}  // namespace
}  // namespace cdvp
