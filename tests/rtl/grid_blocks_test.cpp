// The grid board's new RTL blocks under Verilator (tests/rtl/grid_blocks_top.v)
// driven from C++ with the inputs their C++ models take, result for result:
// the cell-function unit against GridGeometry::cell (float32, fixed32 and
// fixed16) over grids from the bounds pass and from hostile origins and
// scales, with bounds at cell edges, special words and random bit patterns,
// its pipeline held by enable at random; the one-cell filter against
// home_cell_keeps; the cell loader and cell buffer against CellBuffer (the
// slot each box lands in and the load ends in, each entry's words, index and
// first cells, read back through the four ports). docs/grid_board.md ("RTL")
// says what this covers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <random>
#include <vector>

#include "Vgrid_blocks.h"
#include "models/cell_memory/cell_buffer.h"
#include "models/grid_binning/grid_geometry.h"
#include "verilated.h"

namespace cdvp {
namespace {

uint32_t bits_of(float f) {
    uint32_t w;
    std::memcpy(&w, &f, sizeof w);
    return w;
}
float float_of(uint32_t w) {
    float f;
    std::memcpy(&f, &w, sizeof f);
    return f;
}

// One grid the unit is held to: its axis and cells a side.
struct Grid {
    GridAxis axis;
    uint32_t dims = 1;
};

class CellFunctionRtl {
public:
    CellFunctionRtl() : context_(std::make_unique<VerilatedContext>()), top_(std::make_unique<Vgrid_blocks>(context_.get())) {
        top_->clk = 0;
        top_->enable = 0;
        top_->eval();
    }
    ~CellFunctionRtl() { top_->final(); }

    // Every word through the three units on one grid, the enable dropped on
    // about one edge in five; returns the words whose cells differ from the
    // model's (with a message for the first).
    uint64_t check(const Grid& grid, const std::vector<uint32_t>& words, std::mt19937& rng, std::string& first) {
        const std::array<GridAxis, 3> axes{grid.axis, grid.axis, grid.axis};
        const GridGeometry models[3] = {GridGeometry(NumberFormat::float32(), grid.dims, axes),
                                        GridGeometry(NumberFormat::fixed(32), grid.dims, axes),
                                        GridGeometry(NumberFormat::fixed(16), grid.dims, axes)};
        const NumberFormat formats[3] = {NumberFormat::float32(), NumberFormat::fixed(32), NumberFormat::fixed(16)};
        top_->lo = bits_of(grid.axis.lo);
        top_->scale = bits_of(grid.axis.scale);
        top_->dims = grid.dims;
        std::bernoulli_distribution hold(0.2);
        // Four register stages: a word taken at an enabled edge is the cell
        // after the third enabled edge after it. The flush feeds no word (nullopt).
        std::deque<std::optional<uint32_t>> in_flight;
        uint64_t wrong = 0;
        std::size_t next = 0;
        auto pending = [&] {
            return std::any_of(in_flight.begin(), in_flight.end(), [](const auto& w) { return w.has_value(); });
        };
        while (next < words.size() || pending()) {
            const bool enabled = !hold(rng);
            top_->enable = enabled;
            top_->word = next < words.size() ? words[next] : static_cast<uint32_t>(rng());
            tick();
            if (!enabled) continue;
            in_flight.push_back(next < words.size() ? std::optional<uint32_t>(words[next++]) : std::nullopt);
            if (in_flight.size() < 4) continue;
            const std::optional<uint32_t> word = in_flight.front();
            in_flight.pop_front();
            if (!word) continue;
            const uint32_t rtl[3] = {top_->float32_cell, top_->fixed32_cell, top_->fixed16_cell};
            for (int f = 0; f < 3; ++f) {
                const uint32_t model = models[f].cell(0, formats[f].key(*word));
                if (rtl[f] == model) continue;
                ++wrong;
                if (first.empty()) {
                    char line[256];
                    std::snprintf(line, sizeof line, "%s word 0x%08x, lo %a, scale %a, dims %u: RTL cell %u, model %u",
                                  formats[f].name().c_str(), *word, grid.axis.lo, grid.axis.scale, grid.dims, rtl[f],
                                  model);
                    first = line;
                }
            }
        }
        in_flight.clear();
        return wrong;
    }

private:
    void tick() {
        top_->clk = 1;
        top_->eval();
        top_->clk = 0;
        top_->eval();
    }
    std::unique_ptr<VerilatedContext> context_;
    std::unique_ptr<Vgrid_blocks> top_;
};

// Words at and beside the edges of a grid's cells (the ulps either side of
// lo + k / scale), where the rounding of v - lo and of the product decides the cell.
void add_cell_edges(const Grid& grid, std::vector<uint32_t>& words) {
    if (!(grid.axis.scale > 0.0f) || !std::isfinite(grid.axis.scale)) return;
    for (uint32_t k = 0; k <= std::min<uint32_t>(grid.dims, 8); ++k) {
        const float edge = grid.axis.lo + static_cast<float>(k) / grid.axis.scale;
        float v = edge;
        for (int step = 0; step < 3; ++step) v = std::nextafter(v, -INFINITY);
        for (int step = 0; step < 7; ++step, v = std::nextafter(v, INFINITY)) {
            words.push_back(bits_of(v));
            words.push_back(static_cast<uint32_t>(std::max(0.0f, std::min(v, 4.0e9f))));  // a code near it
        }
    }
}

std::vector<uint32_t> special_words() {
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<uint32_t> words = {bits_of(0.0f), bits_of(-0.0f), bits_of(inf), bits_of(-inf), 0x7FC0'0000u,
                                   0xFFC0'0000u, 0x7F80'0001u, 0xFF80'0001u, 1u, 0x8000'0001u, 0x007F'FFFFu,
                                   0x0080'0000u, bits_of(std::numeric_limits<float>::max()),
                                   bits_of(-std::numeric_limits<float>::max()), 0xFFFF'FFFFu, 0x00FF'FFFFu,
                                   0x0100'0001u, 0x0100'0003u, 0xFFFF'FF7Fu, 0xFFFF'FF80u, 0xFFFF'FF81u, 0xFFFFu};
    return words;
}

// A random float across every exponent (subnormals and zeros included), of either sign.
float any_float(std::mt19937& rng) {
    uint32_t w = rng();
    if ((w & 0x7F80'0000u) == 0x7F80'0000u) w ^= 0x4000'0000u;  // finite
    return float_of(w);
}

// Grids the bounds pass makes (GridBounds over random scenes) and hostile
// ones: any finite origin, scales of every magnitude, 0 and infinity.
std::vector<Grid> grids(std::mt19937& rng) {
    std::vector<Grid> out;
    std::uniform_int_distribution<uint32_t> dims(1, 256);
    std::uniform_real_distribution<float> coord(-100.0f, 100.0f);
    for (int s = 0; s < 120; ++s) {
        GridBounds bounds;
        const int n = 2 + s % 30;
        for (int i = 0; i < n; ++i) {
            const float x = coord(rng) * (s % 4 == 0 ? 1e-30f : s % 4 == 1 ? 1e30f : 1.0f);
            const uint32_t keys[6] = {NumberFormat::float32().key(bits_of(x)), 0, 0,
                                      NumberFormat::float32().key(bits_of(x + 1.0f)), 0, 0};
            bounds.add(keys);
        }
        GridConfig config;
        if (s % 5 == 4) config.cell_size = std::abs(coord(rng)) + 0.001f;
        const uint32_t d = s % 7 == 0 ? 256 : s % 7 == 1 ? 1 : dims(rng);
        out.push_back({bounds.geometry(config, d).axis(0), d});
    }
    const float inf = std::numeric_limits<float>::infinity();
    const float scales[] = {0.0f, 1.0f, 0.5f, 3.0f, 1e-3f, 1e3f, 1e30f, 1e-30f, 1e-40f, 1e38f, inf,
                            std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max()};
    for (int s = 0; s < 400; ++s) {
        Grid g;
        g.axis.lo = s % 3 == 0 ? 0.0f : any_float(rng);
        g.axis.scale = s % 2 == 0 ? scales[s / 2 % std::size(scales)] : std::abs(any_float(rng));
        g.dims = s % 11 == 0 ? 256 : dims(rng);
        out.push_back(g);
    }
    return out;
}

TEST(GridCellFunctionRtl, EveryCellEqualsTheModelsInFloat32AndFixedPoint) {
    std::mt19937 rng(35);
    CellFunctionRtl rtl;
    uint64_t checked = 0, wrong = 0;
    std::string first;
    for (const Grid& grid : grids(rng)) {
        std::vector<uint32_t> words = special_words();
        add_cell_edges(grid, words);
        std::uniform_real_distribution<float> around(-4.0f, 4.0f);
        for (int i = 0; i < 600; ++i) {
            switch (i % 4) {
                case 0: words.push_back(static_cast<uint32_t>(rng())); break;
                case 1: words.push_back(bits_of(any_float(rng))); break;
                case 2: {  // near the origin, within a few grid widths: cancellation and every cell
                    const float width = grid.axis.scale > 0 && std::isfinite(grid.axis.scale)
                                            ? static_cast<float>(grid.dims) / grid.axis.scale
                                            : 1.0f;
                    words.push_back(bits_of(grid.axis.lo + around(rng) * width));
                    break;
                }
                default: words.push_back(static_cast<uint32_t>(rng()) >> (rng() % 32)); break;  // small codes
            }
        }
        checked += words.size();
        wrong += rtl.check(grid, words, rng, first);
    }
    EXPECT_EQ(wrong, 0u) << "first: " << first;
    EXPECT_GT(checked, 300000u);
}

TEST(HomeCellFilterRtl, KeepsExactlyTheHitsTheOneCellRuleKeeps) {
    auto context = std::make_unique<VerilatedContext>();
    Vgrid_blocks top(context.get());
    std::mt19937 rng(8);
    uint64_t kept = 0, dropped = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Each trial's cells from three random bytes (so that equal and
        // unequal cells both occur, differing in any bit).
        const uint32_t bytes[3] = {static_cast<uint32_t>(rng() & 0xFF), static_cast<uint32_t>(rng() & 0xFF),
                                   static_cast<uint32_t>(rng() & 0xFF)};
        auto cell = [&] { return bytes[rng() % 3]; };
        uint32_t here[3];
        uint8_t row[3];
        uint8_t columns[15][3];
        for (int a = 0; a < 3; ++a) {
            here[a] = cell();
            row[a] = static_cast<uint8_t>(cell());
        }
        top.here = here[0] | here[1] << 8 | here[2] << 16;
        top.row_first = row[0] | row[1] << 8 | row[2] << 16;
        for (int w = 0; w < 12; ++w) top.column_first[w] = 0;
        for (int k = 0; k < 15; ++k) {
            for (int a = 0; a < 3; ++a) {
                columns[k][a] = static_cast<uint8_t>(cell());
                const int bit = k * 24 + a * 8;
                top.column_first[bit / 32] |= uint32_t{columns[k][a]} << (bit % 32);
                if (bit % 32 > 24) top.column_first[bit / 32 + 1] |= uint32_t{columns[k][a]} >> (32 - bit % 32);
            }
        }
        const uint32_t hits = rng() & 0x7FFF;
        top.hits = hits;
        top.eval();
        for (int k = 0; k < 15; ++k) {
            const bool model = (hits >> k & 1) && home_cell_keeps(row, columns[k], here);
            ASSERT_EQ((top.kept >> k & 1) != 0, model) << "trial " << trial << " lane " << k;
            (model ? kept : dropped) += hits >> k & 1;
        }
    }
    EXPECT_GT(kept, 10000u);  // both outcomes exercised
    EXPECT_GT(dropped, 10000u);
}

// Bits [lo, lo + n) of a Verilator wide signal (n <= 32).
template <class Wide>
uint32_t bits_at(const Wide& wide, uint32_t lo, uint32_t n) {
    uint64_t word = wide[lo / 32];
    if (lo % 32 + n > 32) word |= uint64_t{wide[lo / 32 + 1]} << 32;
    return static_cast<uint32_t>(word >> (lo % 32)) & (n == 32 ? ~0u : (1u << n) - 1);
}

// The harness's loader: 10-bit box indices, 12-bit entry addresses, 64 boxes
// a half, SSRAM latency 2; the cell buffer of an m = 2 board (four ports).
constexpr uint32_t kBoxes = 1024, kEntries = 4096, kHalfDepth = 64, kLatency = 2, kPorts = 4;
constexpr uint32_t kIndexBits = 10, kEntryBits = 24 + kIndexBits + 192;

// An entry as the RTL writes it: {first z, y, x; index; six words}.
struct Entry {
    std::array<uint32_t, 6> words{};
    uint32_t index = 0;
    std::array<uint32_t, 3> first{};
    friend bool operator==(const Entry& a, const Entry& b) {
        return a.words == b.words && a.index == b.index && a.first == b.first;
    }
};
template <class Wide>
Entry entry_at(const Wide& wide, uint32_t base) {
    Entry e;
    for (uint32_t c = 0; c < 6; ++c) e.words[c] = bits_at(wide, base + 32 * c, 32);
    e.index = bits_at(wide, base + 192, kIndexBits);
    for (uint32_t a = 0; a < 3; ++a) e.first[a] = bits_at(wide, base + 192 + kIndexBits + 8 * a, 8);
    return e;
}
std::string describe(const Entry& e) {
    char text[160];
    std::snprintf(text, sizeof text, "box %u, first cells %u %u %u, min x 0x%08x", e.index, e.first[0], e.first[1],
                  e.first[2], e.words[0]);
    return text;
}

TEST(CellLoaderRtl, LoadsLandInTheModelsSlotsWithTheModelsEntriesAndReadBackOnEveryPort) {
    auto context = std::make_unique<VerilatedContext>();
    Vgrid_blocks top(context.get());
    std::mt19937 rng(64);
    // The box store: boxes of a scene, with special words now and then.
    CellBuffer::Store store;
    std::uniform_real_distribution<float> coord(-20.0f, 20.0f);
    const float specials[] = {-0.0f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                              1e-41f, 3e38f};
    for (uint32_t i = 0; i < kBoxes; ++i) {
        for (uint32_t a = 0; a < 3; ++a) {
            const float lo = i % 17 == 0 ? specials[i / 17 % std::size(specials)] : coord(rng);
            store[a].push_back(bits_of(lo));
            store[a + 3].push_back(bits_of(lo + 1.5f));
        }
    }
    std::vector<uint32_t> entries(kEntries);
    for (uint32_t& e : entries) e = rng() % kBoxes;

    const GridSlots slots{3, 1, kLatency};
    CellBuffer model(2, kHalfDepth, slots, NumberFormat::float32());
    std::bernoulli_distribution hold(0.25);
    std::deque<uint32_t> entry_answers(kLatency, 0);  // the SSRAMs' read pipelines, a word a slot
    std::deque<std::array<uint32_t, 6>> box_answers(kLatency, std::array<uint32_t, 6>{});
    // One slot: inputs from reads LAT slots back, the outputs seen, then the edge (enable at random).
    auto slot = [&](bool enabled, auto&& see) {
        top.entry_word = entry_answers.front();
        for (uint32_t c = 0; c < 6; ++c) top.box_words[c] = box_answers.front()[c];
        top.enable = enabled;
        top.eval();
        see();
        const uint32_t entry = top.entry_re ? entries[top.entry_addr] : static_cast<uint32_t>(rng() % kBoxes);
        std::array<uint32_t, 6> box{};
        for (uint32_t c = 0; c < 6; ++c) box[c] = top.box_re ? store[c][top.box_addr] : static_cast<uint32_t>(rng());
        top.clk = 1;
        top.eval();
        top.clk = 0;
        top.eval();
        if (!enabled) return;
        entry_answers.pop_front();
        entry_answers.push_back(entry);
        box_answers.pop_front();
        box_answers.push_back(box);
    };

    uint64_t loads = 0, checked = 0;
    for (int load = 0; load < 120; ++load) {
        const uint32_t half = load % 2;
        const uint32_t count = load % 9 == 0 ? kHalfDepth : 1 + rng() % kHalfDepth;
        const uint32_t first_entry = rng() % (kEntries - count);
        std::array<GridAxis, 3> axes{};
        for (GridAxis& axis : axes) axis = {coord(rng), std::abs(coord(rng)) / 8.0f};
        const uint32_t dims = 1 + rng() % 256;
        const GridGeometry grid(NumberFormat::float32(), dims, axes);
        top.dims = dims;
        for (uint32_t a = 0; a < 3; ++a) {
            top.grid_lo[a] = bits_of(axes[a].lo);
            top.grid_scale[a] = bits_of(axes[a].scale);
        }
        // The model: its slots to the end of the load.
        model.begin(half, entries.data() + first_entry, count);
        uint64_t model_slots = 1;
        while (!model.tick(store, grid)) ++model_slots;
        // The RTL: start in an enabled slot, then slots until done.
        std::vector<std::optional<Entry>> written(kHalfDepth);
        uint64_t rtl_slots = 0;
        bool done = false;
        top.load_start = 1;
        top.load_half = half;
        top.load_count = count;
        top.load_first_entry = first_entry;
        auto see = [&] {
            if (top.load_write) {
                ASSERT_LT(top.load_write_addr, count) << "load " << load;
                written[top.load_write_addr] = entry_at(top.load_write_data, 0);
            }
            done = top.load_done && top.enable;  // a held slot is seen again when it moves
        };
        slot(true, see);
        top.load_start = 0;
        ++rtl_slots;
        while (!done) {
            ASSERT_LT(rtl_slots, 1000u) << "load " << load << " never ends";
            const bool enabled = !hold(rng);
            if (enabled) ++rtl_slots;
            slot(enabled, see);
        }
        ASSERT_EQ(rtl_slots, model_slots) << "load " << load << " of " << count << " boxes";
        EXPECT_EQ(model_slots, slots.load(count));
        EXPECT_EQ(top.load_busy, 0) << "load " << load;
        const CellBuffer::Half& h = model.half(half);
        for (uint32_t p = 0; p < count; ++p) {
            Entry expected;
            for (uint32_t c = 0; c < 6; ++c) expected.words[c] = h.boxes[c].peek(p);
            expected.index = h.index[p];
            for (uint32_t a = 0; a < 3; ++a) expected.first[a] = h.first[a][p];
            ASSERT_TRUE(written[p].has_value()) << "load " << load << " never wrote position " << p;
            ASSERT_EQ(*written[p], expected) << "load " << load << " position " << p << ": RTL "
                                             << describe(*written[p]) << ", model " << describe(expected);
            ++checked;
        }
        // Read back through the four ports of that half.
        for (uint32_t k = 0; k < 8; ++k) {
            top.read_half = half;
            uint32_t at[kPorts];
            top.read_addr = 0;
            for (uint32_t port = 0; port < kPorts; ++port) {
                at[port] = rng() % count;
                top.read_addr |= at[port] << (6 * port);
            }
            slot(true, [] {});
            top.eval();
            for (uint32_t port = 0; port < kPorts; ++port) {
                ASSERT_EQ(entry_at(top.read_data, port * kEntryBits), *written[at[port]])
                    << "load " << load << " port " << port << " position " << at[port];
            }
        }
        ++loads;
    }
    EXPECT_EQ(loads, 120u);
    EXPECT_GT(checked, 3000u);
}

}  // namespace
}  // namespace cdvp
