// The grid board's whole RTL (models/board/rtl/grid_board_top.v) under
// Verilator held to GridClockedEngine edge by edge (LockstepEngine) on the
// grid variants this build holds, on hard scenes: cells that overflow into
// the large sweep, an entry memory that fills, boxes spanning many cells, a
// ground slab, all boxes in one cell, NaN, infinite, -0 and inverted words,
// back-pressure from a FIFO of 2m-1 pairs and overflow pauses of a small pair
// buffer, over several frames (delta uploads). Any difference stops the run
// with the cycle and the signal; the pairs are also held to a float32
// all-pairs oracle and the counters to a clocked run.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "models/board/board_core.h"
#include "models/grid_clocked_engine/grid_clocked_engine.h"
#include "models/rtl_engine/lockstep_engine.h"
#include "models/rtl_engine/rtl_variant.h"
#include "sw/baselines/brute_force.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using testing::CoreRun;
using testing::random_boxes;
using testing::run_core;

// Every pair i < j the comparators report (no board code): the oracle.
PairList oracle(const std::vector<FloatBox>& boxes) {
    PairList pairs;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t j = i + 1; j < boxes.size(); ++j) {
            if (boxes_overlap(boxes[i], boxes[j])) pairs.push_back({i, j});
        }
    }
    return pairs;
}

const BuiltRtlVariant* grid_variant() {
    for (const BuiltRtlVariant& built : built_rtl_variants()) {
        if (built.variant.grid) return &built;
    }
    return nullptr;
}

// The hard scenes, named.
std::vector<std::pair<std::string, std::vector<FloatBox>>> hard_scenes(uint32_t capacity) {
    std::mt19937 rng(35);
    std::vector<std::pair<std::string, std::vector<FloatBox>>> scenes;
    for (uint32_t n : {0u, 1u, 2u, 3u, 90u, 300u, capacity}) {
        scenes.emplace_back("random " + std::to_string(n), random_boxes(n, std::cbrt(float(n)) * 6.0f, 3.0f, rng));
    }
    scenes.emplace_back("one cell", std::vector<FloatBox>(60, FloatBox{{1, 1, 1}, {2, 2, 2}}));
    auto clustered = random_boxes(200, 4.0f, 1.5f, rng);
    for (FloatBox& b : random_boxes(40, 200.0f, 2.0f, rng)) clustered.push_back(b);
    scenes.emplace_back("clustered", clustered);
    auto slab = random_boxes(250, 40.0f, 3.0f, rng);
    slab[17] = FloatBox{{-1000, -1, -1000}, {1000, 0.5f, 1000}};  // a ground slab
    slab[80] = FloatBox{{0, 0, 0}, {30, 30, 30}};                  // spans many cells
    slab[81] = FloatBox{{5, 5, 5}, {25, 6, 25}};
    scenes.emplace_back("slab and large boxes", slab);
    // Pairs that share two, four and eight cells (the one-cell rule reports
    // each once), binned first, among small boxes that fit the 2^3 grid of
    // 150 boxes to [0, 30]^3: cell edges at 15.
    std::vector<FloatBox> shared{{{14, 1, 1}, {16, 2, 2}},     {{14.5f, 1, 1}, {16.5f, 2, 2}},
                                 {{14, 14, 3}, {16, 16, 4}},   {{15.5f, 14.5f, 3}, {17, 15.5f, 4}},
                                 {{14, 14, 14}, {16, 16, 16}}, {{14.5f, 14.5f, 14.5f}, {16.5f, 16.5f, 16.5f}},
                                 {{1, 14, 25}, {2, 16, 26}},   {{1.5f, 15, 25}, {2.5f, 16, 26}}};
    for (const FloatBox& b : random_boxes(142, 29.5f, 0.5f, rng)) shared.push_back(b);
    shared.push_back(FloatBox{{0, 0, 0}, {0.1f, 0.1f, 0.1f}});
    shared.push_back(FloatBox{{29.9f, 29.9f, 29.9f}, {30, 30, 30}});
    scenes.emplace_back("pairs across cell edges", shared);
    // Special words: NaN (excluded), infinities, -0, denormals, inverted boxes.
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float specials[] = {-0.0f, 0.0f, std::numeric_limits<float>::denorm_min(), -inf, inf, nan, 1e-38f, -1e38f};
    auto hard = random_boxes(200, 30.0f, 4.0f, rng);
    for (std::size_t i = 0; i < hard.size(); i += 5) {
        const int a = static_cast<int>(i % 3);
        hard[i].min[a] = specials[(i / 5) % std::size(specials)];
        if (i % 2 == 0) hard[i].max[a] = specials[(i / 5 + 3) % std::size(specials)];
        if (i % 15 == 0) std::swap(hard[i].min[(a + 1) % 3], hard[i].max[(a + 1) % 3]);  // inverted
    }
    scenes.emplace_back("NaN, infinite, -0 and inverted", hard);
    return scenes;
}

TEST(GridBoardLockstep, HardScenesHoldToTheClockedEngineEdgeByEdge) {
    const BuiltRtlVariant* built = grid_variant();
    if (built == nullptr) GTEST_SKIP() << "no grid RTL variant is built (CDVP_RTL_VARIANTS)";
    const RtlVariant& v = built->variant;
    const BoardConfig config = v.board();
    const auto capacity = static_cast<uint32_t>(v.capacity());
    BoardCore lockstep(config, capacity, Fidelity::kLockstep);
    uint32_t frames = 0, pauses = 0;
    uint64_t stalls = 0, large = 0, overflowing = 0, excluded = 0, tiles_over_one = 0;
    for (auto& [name, boxes] : hard_scenes(capacity)) {
        for (int frame = 0; frame < 3; ++frame) {
            SCOPED_TRACE(v.spec() + ": " + name + ", frame " + std::to_string(frame));
            BoardCore clocked(config, capacity, Fidelity::kCycle);
            const CoreRun expected = run_core(clocked, boxes);
            const CoreRun got = run_core(lockstep, boxes);
            ASSERT_EQ(lockstep.engine().divergence(), "");
            EXPECT_EQ(sorted(got.pairs), oracle(boxes));
            EXPECT_EQ(expected.pairs, got.pairs) << "the same pairs in the same order";
            EXPECT_EQ(expected.cycles, got.cycles);
            EXPECT_EQ(expected.stalls, got.stalls);
            EXPECT_EQ(expected.pauses, got.pauses);
            const GridSweepStats stats = lockstep.engine().grid_stats();
            EXPECT_EQ(stats, clocked.engine().grid_stats());
            pauses += got.pauses;
            stalls += got.stalls;
            large += stats.large_boxes;
            overflowing += stats.overflow_boxes;
            excluded += stats.excluded_boxes;
            tiles_over_one += stats.large_boxes > config.grid.cell_capacity ? 1 : 0;
            ++frames;
            // The next frame moves a third of the boxes: a delta upload.
            for (std::size_t i = frame; i < boxes.size(); i += 3) boxes[i].max[0] += 0.75f;
        }
    }
    const auto& engine = dynamic_cast<LockstepEngine&>(lockstep.engine());
    std::cout << "grid lockstep " << v.spec() << ": " << frames << " frames, " << engine.edges_compared()
              << " edges compared, " << stalls << " stall cycles, " << pauses << " pauses, " << large
              << " large boxes (" << overflowing << " overflowing), " << excluded << " excluded\n";
    // The scenes reach what they are for.
    EXPECT_GT(pauses, 0u) << "no overflow pause";
    EXPECT_GT(stalls, 0u) << "no back-pressure";
    EXPECT_GT(overflowing, 0u) << "no cell or entry overflow";
    EXPECT_GT(excluded, 0u) << "no NaN box";
    EXPECT_GT(tiles_over_one, 0u) << "no sweep with more than one large tile";
}

// The check itself: a model whose cells hold one box fewer than the RTL's
// must part from it, naming the cycle and the signal.
TEST(GridBoardLockstep, AModelOfAnotherGridPartsFromTheRtl) {
    const BuiltRtlVariant* built = grid_variant();
    if (built == nullptr) GTEST_SKIP() << "no grid RTL variant is built (CDVP_RTL_VARIANTS)";
    const BoardConfig rtl = built->variant.board();
    BoardConfig model = rtl;
    model.grid.cell_capacity -= 1;
    std::mt19937 rng(11);
    const auto boxes = random_boxes(120, 12.0f, 3.0f, rng);
    const CoordinateStore store = testing::float32_store(boxes);
    const auto capacity = static_cast<uint32_t>(built->variant.capacity());
    LockstepEngine lockstep(model, rtl, capacity);
    lockstep.start(store, 120);
    const uint64_t edges = lockstep.segment_edges();
    const LockstepDivergence* divergence = lockstep.first_divergence();
    ASSERT_NE(divergence, nullptr) << "the lockstep check missed a grid of smaller cells";
    EXPECT_NE(std::string(divergence->what()).find("cycle " + std::to_string(divergence->cycle())), std::string::npos);
    EXPECT_EQ(lockstep.divergence(), divergence->what());
    // Past the difference the RTL goes on alone and ends its segment as it would unchecked.
    RtlEngine alone(rtl, capacity);
    alone.start(store, 120);
    EXPECT_EQ(edges, alone.segment_edges());
}

// A grid board the top cannot run is refused in one line naming what, before
// any model is looked for; one it can run is served (by a built variant or
// one compiled on first use).
TEST(GridBoardLockstep, WhatTheGridTopCannotRunIsRefusedInOneLine) {
    BoardConfig grid;
    grid.algorithm = BoardAlgorithm::kGrid;
    EXPECT_EQ(rtl_unsupported(grid), "");
    BoardConfig slow = grid, late = grid, huge = grid;
    slow.tiles.cycles_per_box = 2;
    late.tiles.load_latency_cycles = 9;
    huge.grid.dims = 100;
    const std::pair<BoardConfig, const char*> refused[] = {
        {slow, "reads a box from six SSRAM banks in one slot (q = 1); cycles_per_box is 2"},
        {late, "SSRAM read latency is at most 8 slots; it is 9"},
        {huge, "holds at most 262144 cells (a register file); board.grid.dims 100 makes 1000000"}};
    for (const auto& [config, why] : refused) {
        EXPECT_NE(rtl_unsupported(config).find(why), std::string::npos) << rtl_unsupported(config);
        try {
            rtl_variant_for(config, 300);
            ADD_FAILURE() << "the grid RTL cannot run a board with " << why;
        } catch (const std::invalid_argument& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind("fidelity rtl: ", 0), 0u) << what;
            EXPECT_NE(what.find(why), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

}  // namespace
}  // namespace cdvp
