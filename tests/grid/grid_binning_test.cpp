// The binning stage's blocks: the cell function, the bounds, the
// classification, and the cell memory's passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

#include "models/cell_memory/cell_table.h"
#include "models/grid_binning/grid_geometry.h"

namespace cdvp {
namespace {

uint32_t bits(float value) {
    uint32_t word;
    std::memcpy(&word, &value, sizeof word);
    return word;
}

GridGeometry float_grid(uint32_t dims, float lo, float scale) {
    return GridGeometry(NumberFormat::float32(), dims, {GridAxis{lo, scale}, GridAxis{lo, scale}, GridAxis{lo, scale}});
}

// a <= b in the format gives cell(a) <= cell(b): every rule of the board rests on it.
TEST(GridGeometry, TheCellFunctionIsMonotoneInTheFormatsOrder) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<uint32_t> any;
    const float inf = std::numeric_limits<float>::infinity();
    for (const NumberFormat format : {NumberFormat::float32(), NumberFormat::fixed(12), NumberFormat::fixed(32)}) {
        for (const GridAxis axis : {GridAxis{-3.5f, 0.7f}, GridAxis{0.0f, 1e-30f}, GridAxis{1e30f, 3e20f},
                                    GridAxis{-1e38f, 1e-37f}, GridAxis{0.0f, 0.0f}, GridAxis{5.0f, inf}}) {
            const GridGeometry grid(format, 37, {axis, axis, axis});
            std::vector<uint32_t> keys;
            for (int k = 0; k < 20000; ++k) {
                const uint32_t word = any(rng) & format.word_mask();
                if (!format.excluded(word)) keys.push_back(format.key(word));
            }
            for (float v : {0.0f, -0.0f, 1.0f, -1.0f, inf, -inf, 3.4e38f, -3.4e38f, 1e-45f, -3.5f}) {
                if (format.is_float()) keys.push_back(format.key(bits(v)));
            }
            std::sort(keys.begin(), keys.end());
            uint32_t previous = 0;
            for (uint32_t key : keys) {
                const uint32_t cell = grid.cell(0, key);
                ASSERT_LT(cell, 37u);
                ASSERT_LE(previous, cell) << format.name() << " key " << key << " lo " << axis.lo << " scale " << axis.scale;
                previous = cell;
            }
        }
    }
}

TEST(GridGeometry, InfinitiesTakeTheEndCellsAndZerosAreOne) {
    const GridGeometry grid = float_grid(10, -1.0f, 2.0f);
    const NumberFormat f32;
    EXPECT_EQ(0u, grid.cell(0, f32.key(bits(-std::numeric_limits<float>::infinity()))));
    EXPECT_EQ(9u, grid.cell(0, f32.key(bits(std::numeric_limits<float>::infinity()))));
    EXPECT_EQ(grid.cell(1, f32.key(bits(0.0f))), grid.cell(1, f32.key(bits(-0.0f))));
    EXPECT_EQ(2u, grid.cell(2, f32.key(bits(0.0f))));     // (0 + 1) x 2
    EXPECT_EQ(4u, grid.cell(2, f32.key(bits(1.25f))));    // (1.25 + 1) x 2 = 4.5
    EXPECT_EQ(0u, grid.cell(2, f32.key(bits(-7.0f))));    // below the origin
    EXPECT_EQ(9u, grid.cell(2, f32.key(bits(1e30f))));    // past the last cell
}

TEST(GridBounds, FitsTheGridToTheFiniteCentresOrToTheCellSize) {
    const NumberFormat f32;
    GridBounds bounds(f32);
    const float inf = std::numeric_limits<float>::infinity();
    auto add = [&](float lo, float hi) {
        uint32_t keys[6];
        for (uint32_t c = 0; c < 6; ++c) keys[c] = f32.key(bits(c < 3 ? lo : hi));
        bounds.add(keys);
    };
    add(-3.0f, -1.0f);  // centre -2
    add(4.0f, 8.0f);    // centre 6
    add(-inf, 6.0f);    // an infinite centre is no bound of the grid
    add(-1e4f, 1e4f);   // a slab centred at 0 does not stretch it
    GridConfig config;
    const GridGeometry fitted = bounds.geometry(config, 8);
    EXPECT_EQ(-2.0f, fitted.axis(0).lo);
    EXPECT_EQ(1.0f, fitted.axis(1).scale);  // 8 cells over [-2, 6]
    config.cell_size = 0.5f;
    EXPECT_EQ(2.0f, bounds.geometry(config, 8).axis(2).scale);
    // No finite centre on an axis: one cell, scale 0.
    GridBounds empty(f32);
    EXPECT_EQ(0.0f, empty.geometry(GridConfig{}, 8).axis(0).scale);
}

TEST(GridGeometry, ClassifiesInvertedAndSpanningBoxes) {
    const GridGeometry grid = float_grid(16, 0.0f, 1.0f);
    const NumberFormat f32;
    auto keys = [&](float x0, float x1, float y0, float y1, float z0, float z1, uint32_t (&out)[6]) {
        const float v[6] = {x0, y0, z0, x1, y1, z1};
        for (uint32_t c = 0; c < 6; ++c) out[c] = f32.key(bits(v[c]));
    };
    uint32_t k[6];
    CellRange range;
    keys(1.5f, 2.5f, 3.0f, 3.0f, 0.0f, 0.5f, k);
    ASSERT_EQ(BoxClass::kCandidate, grid.classify(k, 8, range));
    EXPECT_EQ(2u, range.cells());
    EXPECT_EQ(1u, range.lo[0]);
    EXPECT_EQ(2u, range.hi[0]);
    keys(1.5f, 4.5f, 0.0f, 1.0f, 0.0f, 0.5f, k);  // 4 x 2 x 1 = 8
    EXPECT_EQ(BoxClass::kCandidate, grid.classify(k, 8, range));
    keys(1.5f, 4.5f, 0.0f, 2.0f, 0.0f, 0.5f, k);  // 4 x 3 x 1 = 12
    EXPECT_EQ(BoxClass::kSpanning, grid.classify(k, 8, range));
    keys(2.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, k);
    EXPECT_EQ(BoxClass::kInverted, grid.classify(k, 8, range));
    keys(0.0f, -0.0f, 0.0f, 0.0f, 0.0f, 0.0f, k);  // -0 == +0: not inverted
    EXPECT_EQ(BoxClass::kCandidate, grid.classify(k, 8, range));
}

// A run of boxes in bulk (the fast engine's passes 1 and 2) gives the grid
// the bounds add() gives it, and each box the keys, NaN flag, cells and class
// that cell() and classify() give it alone.
TEST(GridGeometry, ARunOfBoxesBinsAsEachBoxAlone) {
    std::mt19937 rng(35);
    std::uniform_int_distribution<uint32_t> any;
    const float inf = std::numeric_limits<float>::infinity();
    const uint32_t specials[] = {bits(0.0f), bits(-0.0f), bits(inf), bits(-inf), 0x7FC0'0000u, 0xFFC0'0001u,
                                 0x0000'0001u, 0x8000'0001u, bits(1e38f), bits(-1e38f), bits(29.0f), 29u};
    for (const NumberFormat format : {NumberFormat::float32(), NumberFormat::fixed(12), NumberFormat::fixed(32)}) {
        for (const GridAxis axis : {GridAxis{-3.5f, 0.7f}, GridAxis{0.0f, 1e-30f}, GridAxis{-1e38f, 1e-37f},
                                    GridAxis{0.0f, 0.0f}, GridAxis{5.0f, inf}, GridAxis{-8.0f, 2.25f},
                                    GridAxis{0.0f, 1.0f}}) {
            const GridGeometry grid(format, 29, {axis, axis, axis});
            // 300 boxes: a full run and a partial one; small words near the
            // grid, any words, and the special values (29: the far edge).
            const uint32_t n = 300;
            std::vector<uint32_t> columns[6];
            for (uint32_t k = 0; k < n; ++k) {
                for (auto& column : columns) {
                    const uint32_t pick = any(rng) % 4;
                    uint32_t word = pick == 0   ? specials[any(rng) % 12]
                                    : pick == 1 ? any(rng)
                                                : (format.is_float() ? bits(static_cast<float>(any(rng) % 4000) / 100.0f - 8.0f)
                                                                     : any(rng) % 64);
                    column.push_back(word & format.word_mask());
                }
            }
            const uint32_t* words[6];
            for (uint32_t c = 0; c < 6; ++c) words[c] = columns[c].data();
            // The bounds: box by box, and a run at a time.
            GridBounds alone_bounds(format), run_bounds(format);
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t box_words[6], keys[6];
                for (uint32_t c = 0; c < 6; ++c) {
                    box_words[c] = columns[c][i];
                    keys[c] = format.key(box_words[c]);
                }
                if (!excluded_box(format, box_words)) alone_bounds.add(keys);
            }
            for (uint32_t begin = 0; begin < n; begin += BoundRun::kBoxes) {
                run_bounds.add_run(words, begin, std::min(BoundRun::kBoxes, n - begin));
            }
            const GridGeometry alone_fit = alone_bounds.geometry(GridConfig{}, 29);
            const GridGeometry run_fit = run_bounds.geometry(GridConfig{}, 29);
            for (uint32_t a = 0; a < 3; ++a) {
                EXPECT_EQ(bits(alone_fit.axis(a).lo), bits(run_fit.axis(a).lo)) << format.name();
                EXPECT_EQ(bits(alone_fit.axis(a).scale), bits(run_fit.axis(a).scale)) << format.name();
            }
            auto run = std::make_unique<BoundRun>();
            for (uint32_t begin = 0; begin < n; begin += BoundRun::kBoxes) {
                const uint32_t count = std::min(BoundRun::kBoxes, n - begin);
                grid.fill_run(words, begin, count, *run);
                for (uint32_t k = 0; k < count; ++k) {
                    uint32_t keys[6], box_words[6];
                    for (uint32_t c = 0; c < 6; ++c) {
                        box_words[c] = columns[c][begin + k];
                        keys[c] = format.key(box_words[c]);
                        ASSERT_EQ(keys[c], run->key[c][k]);
                        ASSERT_EQ(grid.cell(c % 3, keys[c]), run->cell[c][k]) << format.name() << " word " << box_words[c];
                    }
                    const bool excluded = excluded_box(format, box_words);
                    ASSERT_EQ(excluded, run->excluded[k] != 0);
                    if (excluded) continue;
                    CellRange alone, in_run;
                    const BoxClass verdict = grid.classify(keys, 8, alone);
                    ASSERT_EQ(verdict, grid.classify_run(*run, k, 8, in_run));
                    if (verdict != BoxClass::kInverted) {
                        EXPECT_EQ(alone.lo, in_run.lo);
                        EXPECT_EQ(alone.hi, in_run.hi);
                    }
                }
            }
        }
    }
}

// A box with a NaN in a single word is left out of the bounds whole, in a
// run as alone: here its x extent would otherwise widen the grid.
TEST(GridBounds, ARunLeavesOutABoxWithANaNInAnyWord) {
    for (uint32_t nan_at = 0; nan_at < 6; ++nan_at) {
        uint32_t column[6][2];
        for (uint32_t c = 0; c < 6; ++c) {
            column[c][0] = bits(c < 3 ? 1.0f : 2.0f);
            column[c][1] = bits(c < 3 ? 7.0f : 9.0f);
        }
        column[nan_at][1] = 0x7FC0'0000u;
        const uint32_t* words[6];
        for (uint32_t c = 0; c < 6; ++c) words[c] = column[c];
        GridBounds bounds;
        bounds.add_run(words, 0, 2);
        const GridGeometry grid = bounds.geometry(GridConfig{}, 4);
        for (uint32_t a = 0; a < 3; ++a) {
            EXPECT_EQ(1.5f, grid.axis(a).lo) << "NaN in word " << nan_at;
            EXPECT_EQ(0.0f, grid.axis(a).scale) << "NaN in word " << nan_at;
        }
    }
}

TEST(CellTable, CountsScansAndPlacesBoxesWholeOrNotAtAll) {
    const GridGeometry grid = float_grid(4, 0.0f, 1.0f);
    CellTable table;
    table.reset(grid.cells(), 2, 7);
    CellRange one;  // cell (1, 1, 1)
    one.lo = one.hi = {1, 1, 1};
    CellRange two = one;  // cells (1, 1, 1) and (2, 1, 1)
    two.hi[0] = 2;
    EXPECT_TRUE(table.count(one, grid));
    EXPECT_TRUE(table.count(two, grid));
    EXPECT_FALSE(table.count(two, grid)) << "cell (1, 1, 1) is full";
    EXPECT_EQ(1u, table.word(grid.linear(2, 1, 1))) << "a refused box counts nowhere";
    EXPECT_TRUE(table.count(CellRange{{0, 0, 0}, {1, 1, 0}}, grid));  // four more entries: 7 in all
    EXPECT_EQ(7u, table.entries());
    EXPECT_FALSE(table.count(CellRange{{3, 3, 3}, {3, 3, 3}}, grid)) << "the entry memory is full";
    table.scan();
    ASSERT_EQ(1u, table.busy_cells().size());
    const BusyCell busy = table.busy_cells()[0];
    EXPECT_EQ(grid.linear(1, 1, 1), busy.cell);
    EXPECT_EQ(2u, busy.count);
    table.place(4, one, grid);
    table.place(9, two, grid);
    table.place(11, CellRange{{0, 0, 0}, {1, 1, 0}}, grid);
    EXPECT_EQ(4u, table.list(busy)[0]);
    EXPECT_EQ(9u, table.list(busy)[1]);
}

}  // namespace
}  // namespace cdvp
