// The grid board's binning sequencer RTL (models/grid_clocked_engine/rtl/
// grid_sequencer.v, with the cell loader and an SSRAM box store around it:
// tests/rtl/grid_sequencer_top.v) stepped edge by edge beside
// GridClockedEngine on the same scenes: after every edge the pass, the box,
// the busy cell, the large tile, whether the loader is busy and whether the
// lanes wait for it, and the last window issued; every slot's kind and
// window as it leaves the engine's pipeline; the grid registers at the end.
// The engine's stalls and pauses hold the RTL's slots (its enable).
// docs/grid_board.md ("RTL") says what this covers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vgrid_sequencer.h"
#include "models/block_ram/block_ram.h"
#include "models/grid_clocked_engine/grid_clocked_engine.h"
#include "tests/fast_engine/word_scenes.h"
#include "verilated.h"

namespace cdvp {
namespace {

// One harness of the model's two (f_: float32, m = 3, SSRAM latency 2;
// x_: fixed16, m = 1, latency 0), its ports by name.
#define CDVP_HARNESS(Name, P, Width)                                                         \
    struct Name {                                                                            \
        Vgrid_sequencer& t;                                                                  \
        static constexpr uint32_t kWidth = Width;                                            \
        void settings(const BoardConfig& c, uint32_t objects) {                              \
            t.P##_objects = objects;                                                         \
            t.P##_dims_setting = c.grid.dims;                                                \
            uint32_t size;                                                                   \
            std::memcpy(&size, &c.grid.cell_size, sizeof size);                              \
            t.P##_cell_size = size;                                                          \
            t.P##_capacity = c.grid.cell_capacity;                                           \
            t.P##_max_span = c.grid.max_span;                                                \
            t.P##_entry_capacity = static_cast<uint32_t>(c.grid.entry_capacity);             \
        }                                                                                    \
        void store(uint32_t address, const uint32_t (&words)[kCoordinates]) {                \
            for (uint32_t k = 0; k < (6 * Width + 31) / 32; ++k) t.P##_store_words[k] = 0;                           \
            for (uint32_t c = 0; c < kCoordinates; ++c) {                                    \
                const uint64_t word = words[c] & (Width == 32 ? 0xFFFFFFFFull : (1ull << Width) - 1); \
                const uint32_t bit = c * Width;                                              \
                t.P##_store_words[bit / 32] |= static_cast<uint32_t>(word << bit % 32);      \
                if (bit % 32 + Width > 32) t.P##_store_words[bit / 32 + 1] |= static_cast<uint32_t>(word >> (32 - bit % 32)); \
            }                                                                                \
            t.P##_store_addr = address;                                                      \
            t.P##_store_write = 1;                                                           \
        }                                                                                    \
        void end_store() { t.P##_store_write = 0; }                                          \
        uint8_t& start() { return t.P##_start; }                                             \
        uint8_t& enable() { return t.P##_enable; }                                           \
        Probes probes() const {                                                              \
            return {t.P##_pass, t.P##_box, t.P##_cell_number, t.P##_tile, t.P##_loading != 0, \
                    t.P##_waiting != 0, {t.P##_last_row, t.P##_last_column, t.P##_last_lanes}}; \
        }                                                                                    \
        Issued slot() const {                                                                \
            return {t.P##_slot_kind, {t.P##_window_row, t.P##_window_column, t.P##_window_lanes}}; \
        }                                                                                    \
        std::array<GridAxis, 3> grid() const {                                               \
            std::array<GridAxis, 3> axes;                                                    \
            for (uint32_t a = 0; a < 3; ++a) {                                               \
                std::memcpy(&axes[a].lo, &t.P##_lo[a], sizeof(float));                       \
                std::memcpy(&axes[a].scale, &t.P##_scale[a], sizeof(float));                 \
            }                                                                                \
            return axes;                                                                     \
        }                                                                                    \
        GridSweepStats stats() const {                                                       \
            return {t.P##_dims, t.P##_large_boxes, t.P##_overflow_boxes, t.P##_excluded_boxes, \
                    t.P##_cell_entries, t.P##_busy_cells, t.P##_slots};                      \
        }                                                                                    \
    };

// What the engine's probes show after an edge.
struct Probes {
    uint32_t pass, box, cell, tile;
    bool loading, waiting;
    PortWindow last;
};
// A slot as issued: its kind (GridClockedEngine::Slot::Kind) and window.
struct Issued {
    uint32_t kind;
    PortWindow window;
};

CDVP_HARNESS(Float32Harness, f, 32)
CDVP_HARNESS(Fixed16Harness, x, 16)

Probes engine_probes(const GridClockedEngine& e) {
    return {static_cast<uint32_t>(e.pass()), e.box(), e.cell(), e.tile(), e.loading(), e.waiting(), e.last_issue()};
}

std::string describe(const Probes& p) {
    char line[200];
    std::snprintf(line, sizeof line, "pass %s box %u cell %u tile %u loading %d waiting %d last (%u, %u, %u)",
                  to_string(static_cast<GridClockedEngine::Pass>(p.pass)), p.box, p.cell, p.tile, p.loading,
                  p.waiting, p.last.row, p.last.first_column, p.last.valid_lanes);
    return line;
}

bool same(const PortWindow& a, const PortWindow& b) {
    return a.row == b.row && a.first_column == b.first_column && a.valid_lanes == b.valid_lanes;
}
bool same(const Probes& a, const Probes& b) {
    return a.pass == b.pass && a.box == b.box && a.cell == b.cell && a.tile == b.tile && a.loading == b.loading &&
           a.waiting == b.waiting && same(a.last, b.last);
}

// What the sweeps met, so that the test knows it reached each path.
struct Seen {
    uint64_t overflow_boxes = 0, excluded_boxes = 0, busy_cells = 0, pauses = 0, stalls = 0;
    uint64_t subnormal_scales = 0, infinite_scales = 0;  // from extents near FLT_MAX and subnormal ones
    uint32_t tiles = 0;
} seen;

void tick(Vgrid_sequencer& top) {
    top.clk = 1;
    top.eval();
    top.clk = 0;
    top.eval();
}

// The setup's origins and scales, bit for bit, against GridBounds over the
// boxes the model's bounds pass takes (those not excluded).
void expect_grid(const BoardConfig& config, const testing::WordScene& scene, const std::array<GridAxis, 3>& rtl) {
    GridBounds bounds(config.format);
    for (uint32_t i = 0; i < scene.size(); ++i) {
        uint32_t words[kCoordinates], keys[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            words[c] = scene.words[c][i];
            keys[c] = config.format.key(words[c]);
        }
        if (!excluded_box(config.format, words)) bounds.add(keys);
    }
    const GridGeometry grid = bounds.geometry(config.grid, config.grid.dims_for(scene.size()));
    for (uint32_t a = 0; a < 3; ++a) {
        const float scale = grid.axis(a).scale;
        seen.subnormal_scales += scale > 0.0f && scale < std::numeric_limits<float>::min();
        seen.infinite_scales += std::isinf(scale);
        EXPECT_EQ(ComparisonUnit::as_bits(rtl[a].lo), ComparisonUnit::as_bits(grid.axis(a).lo)) << "axis " << a << " origin";
        EXPECT_EQ(ComparisonUnit::as_bits(rtl[a].scale), ComparisonUnit::as_bits(grid.axis(a).scale))
            << "axis " << a << " scale " << rtl[a].scale << ", model " << grid.axis(a).scale;
    }
}

// The model and the RTL through one sweep; returns the edges compared.
template <class Harness>
uint64_t sweep(Vgrid_sequencer& top, GridClockedEngine& engine, const BoardConfig& config,
               const testing::WordScene& scene) {
    Harness h{top};
    auto tick = [&top] { cdvp::tick(top); };
    const uint32_t n = scene.size();
    h.enable() = 0;
    for (uint32_t i = 0; i < n; ++i) {
        uint32_t words[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) words[c] = scene.words[c][i];
        h.store(i, words);
        tick();
    }
    h.end_store();
    h.settings(config, n);
    const CoordinateStore store = testing::store_of(scene);
    engine.start(store, n);
    h.start() = 1;
    tick();
    h.start() = 0;

    // The slots the RTL issued, to meet the engine's as they leave its pipeline.
    const size_t line = BlockRam::kReadLatencyCycles + config.compare.latency_cycles;
    std::vector<Issued> issued;
    uint64_t edges = 0;
    while (engine.state() != SweepState::kDone) {
        if (engine.state() == SweepState::kPaused) {
            engine.resume();
            ++seen.pauses;
        }
        const Issued slot = h.slot();
        engine.advance_to(engine.edges() + 1);
        const bool enabled = !engine.stalled();
        h.enable() = enabled;
        tick();
        ++edges;
        const Probes model = engine_probes(engine), rtl = h.probes();
        if (!same(model, rtl)) {
            ADD_FAILURE() << "edge " << edges << ": model " << describe(model) << "; RTL " << describe(rtl);
            return edges;
        }
        if (!enabled) {
            ++seen.stalls;
            continue;
        }
        issued.push_back(slot);
        if (issued.size() < line) continue;
        const Issued& leaving = issued[issued.size() - line];
        const GridClockedEngine::Slot& out = engine.compare_output();
        if (leaving.kind != out.kind || (out.kind == GridClockedEngine::Slot::kSweep && !same(leaving.window, out.window))) {
            ADD_FAILURE() << "edge " << edges << ": slot " << issued.size() - line << " kind " << out.kind << " window ("
                          << out.window.row << ", " << out.window.first_column << ", " << out.window.valid_lanes
                          << "), RTL kind " << leaving.kind << " (" << leaving.window.row << ", "
                          << leaving.window.first_column << ", " << leaving.window.valid_lanes << ")";
            return edges;
        }
    }
    EXPECT_EQ(h.stats(), engine.grid_stats()) << "the grid registers";
    if (n >= 2) expect_grid(config, scene, h.grid());
    const GridSweepStats stats = engine.grid_stats();
    seen.overflow_boxes += stats.overflow_boxes;
    seen.excluded_boxes += stats.excluded_boxes;
    seen.busy_cells += stats.busy_cells;
    seen.tiles = std::max(seen.tiles, engine.tile());
    return edges;
}

// A new engine and the RTL from reset, through two sweeps of the scene (the
// second from what the first left: the count table cleared, the probes kept).
template <class Harness>
uint64_t lockstep(Vgrid_sequencer& top, const BoardConfig& config, const testing::WordScene& scene) {
    top.reset = 1;
    tick(top);
    top.reset = 0;
    GridClockedEngine engine(config, scene.size());
    const uint64_t edges = sweep<Harness>(top, engine, config, scene);
    if (::testing::Test::HasFailure()) return edges;
    return edges + sweep<Harness>(top, engine, config, scene);
}

struct Shape {
    uint32_t fifo, drain, buffer;  // the pair collector: stalls and pauses
    uint32_t dims, capacity, span;
    float cell_size;
    uint64_t entry_capacity;
};

BoardConfig board_of(const Shape& s, uint32_t m, uint32_t latency, NumberFormat format) {
    BoardConfig config;
    const uint32_t lanes = 2 * m - 1;
    config.algorithm = BoardAlgorithm::kGrid;
    config.format = format;
    config.m = m;
    config.collector.fifo_depth = std::max(s.fifo, lanes);  // a cycle's hits at least
    config.collector.drain_per_cycle = s.drain;
    config.collector.buffer_depth = s.buffer;
    config.tiles.load_latency_cycles = latency;
    config.tiles.cycles_per_box = 1;
    config.grid.dims = s.dims;
    config.grid.cell_capacity = s.capacity;
    config.grid.max_span = s.span;
    config.grid.cell_size = s.cell_size;
    config.grid.entry_capacity = s.entry_capacity;
    return config;
}

// Within the harness's memories: 1,024 boxes, cells of up to 64, 16^3
// cells, 8,192 entries. Small FIFOs and buffers (back-pressure, pauses),
// fitted, fixed-size and set grids, small cells (overflow), a small entry
// memory (entry overflow) and narrow and wide spans (large boxes).
const Shape kShapes[] = {
    {5, 1, 7, 0, 64, 8, 0.0f, 8192},   {15, 1, 262144, 0, 64, 8, 0.0f, 8192}, {3, 2, 40, 4, 9, 2, 0.0f, 8192},
    {200, 4, 1, 0, 16, 1, 0.0f, 100},  {1, 1, 13, 11, 3, 27, 0.0f, 8192},     {15, 1, 5000, 0, 64, 27, 2.5f, 8192},
};

class GridSequencerRtl : public ::testing::Test {
protected:
    GridSequencerRtl() : context_(std::make_unique<VerilatedContext>()), top_(std::make_unique<Vgrid_sequencer>(context_.get())) {
        top_->clk = 0;
        top_->eval();
    }
    ~GridSequencerRtl() override { top_->final(); }
    std::unique_ptr<VerilatedContext> context_;
    std::unique_ptr<Vgrid_sequencer> top_;
};

TEST_F(GridSequencerRtl, Float32ScenesEdgeForEdgeWithTheClockedEngine) {
    seen = Seen{};
    std::mt19937 rng(41);
    uint64_t edges = 0, sweeps = 0;
    std::vector<testing::WordScene> scenes;
    for (uint32_t n : {0u, 1u, 2u, 3u, 90u, 300u}) {
        scenes.push_back(testing::random_scene(n, 2.2f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng));
    }
    scenes.push_back(testing::overlapping_scene(100, rng));  // one cell: overflow into the large sweep
    scenes.push_back(testing::clustered_scene(200, 4, rng));
    scenes.push_back(testing::denormal_scene(80, rng));
    auto slab = testing::random_scene(250, 10.0f, 2.0f, rng);
    const float ground[6] = {-1e3f, -1e3f, 0.0f, 1e3f, 1e3f, 0.5f};
    for (uint32_t c = 0; c < kCoordinates; ++c) slab.words[c].insert(slab.words[c].begin() + 17, ComparisonUnit::as_bits(ground[c]));
    scenes.push_back(slab);
    auto special = testing::random_scene(200, 8.0f, 2.0f, rng);
    testing::sprinkle_special_values(special, 0.05, rng);  // NaN (excluded), infinities, inverted boxes
    scenes.push_back(special);
    // Extents near FLT_MAX (subnormal scales), subnormal extents (infinite
    // scales) and grids of every magnitude between: the setup's divider.
    for (float factor : {4e37f, 1e-39f, 1e-44f, 1e30f, 1e-30f}) {
        auto scaled = testing::random_scene(60, 10.0f, 3.0f, rng);
        for (auto& words : scaled.words) {
            for (uint32_t& w : words) w = ComparisonUnit::as_bits((ComparisonUnit::as_float(w) - 5.0f) * factor);
        }
        scenes.push_back(scaled);
    }
    for (const auto& scene : scenes) {
        for (const Shape& shape : kShapes) {
            edges += lockstep<Float32Harness>(*top_, board_of(shape, 3, 2, NumberFormat::float32()), scene);
            sweeps += 2;
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(edges, 100000u);
    EXPECT_GT(seen.overflow_boxes, 100u);  // full cells and a full entry memory
    EXPECT_GT(seen.excluded_boxes, 10u);   // NaN bounds
    EXPECT_GT(seen.busy_cells, 1000u);
    EXPECT_GT(seen.tiles, 10u);             // many large tiles in one sweep
    EXPECT_GT(seen.pauses, 100u);           // a full pair buffer
    EXPECT_GT(seen.stalls, 10000u);         // back-pressure from the pair FIFO
    EXPECT_GT(seen.subnormal_scales, 0u);   // the divider's quotient below the normal range
    EXPECT_GT(seen.infinite_scales, 0u);    // and beyond FLT_MAX (a subnormal extent)
    std::printf("%llu sweeps, %llu edges compared\n", static_cast<unsigned long long>(sweeps),
                static_cast<unsigned long long>(edges));
}

TEST_F(GridSequencerRtl, Fixed16ScenesEdgeForEdgeWithTheClockedEngine) {
    std::mt19937 rng(42);
    uint64_t edges = 0;
    const NumberFormat format = NumberFormat::fixed(16);
    for (uint32_t n : {2u, 120u, 300u}) {
        for (double share : {0.002, 0.05}) {
            const auto scene = testing::fixed_scene(n, format, share, rng);
            for (Shape shape : kShapes) {
                if (shape.cell_size != 0.0f) shape.cell_size = 3000.0f;  // in codes
                edges += lockstep<Fixed16Harness>(*top_, board_of(shape, 1, 0, format), scene);
                if (HasFailure()) return;
            }
        }
    }
    EXPECT_GT(edges, 100000u);
    std::printf("%llu edges compared\n", static_cast<unsigned long long>(edges));
}

}  // namespace
}  // namespace cdvp
