// The board RTL under Verilator held to the clocked engine edge by edge
// (LockstepEngine) on every RTL variant this build holds: N across the
// block RAM border, several frames (so the RTL engine's uploads are deltas),
// dense scenes that stall the FIFO and pause on the pair buffer, tiles, and
// coordinate words no scene makes (NaN, infinities, -0, denormals, or raw
// codes in fixed point). Any difference stops the run with the cycle and the
// signal (LockstepDivergence); the results are also held to a clocked run.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <sstream>

#include "models/board/board_core.h"
#include "models/clocked_engine/clocked_engine.h"
#include "models/rtl_engine/lockstep_engine.h"
#include "models/rtl_engine/rtl_variant.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using testing::CoreRun;
using testing::random_boxes;
using testing::run_core;

// Words no random scene holds: special floats, and boxes made of them.
std::vector<FloatBox> with_hard_words(std::vector<FloatBox> boxes, std::mt19937& rng) {
    const float specials[] = {-0.0f, 0.0f, std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::infinity(),
                              std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(), 1e-38f, -1e38f};
    std::uniform_int_distribution<std::size_t> pick(0, std::size(specials) - 1);
    for (std::size_t i = 0; i < boxes.size(); i += 7) {
        const int a = static_cast<int>(i % 3);
        boxes[i].min[a] = specials[pick(rng)];
        if (i % 2 == 0) boxes[i].max[a] = specials[pick(rng)];
    }
    return boxes;
}

std::vector<uint32_t> sizes_for(const RtlVariant& v) {
    const auto capacity = static_cast<uint32_t>(v.capacity());
    std::vector<uint32_t> sizes{1, 2 * v.m - 1, 2 * v.m + 1, std::min(capacity, 97u)};
    // Across the 512-box block RAM border (and a tile border when tiled).
    if (capacity > 512) sizes.insert(sizes.end(), {511, 512, 513, capacity});
    else sizes.push_back(capacity);
    if (v.tile_boxes > 0) sizes.insert(sizes.end(), {v.tile_boxes, v.tile_boxes + 1, 3 * v.tile_boxes - 1});
    return sizes;
}

class RtlLockstep : public ::testing::TestWithParam<std::size_t> {};

TEST_P(RtlLockstep, HoldsToTheClockedEngineEdgeByEdge) {
    const RtlVariant& v = built_rtl_variants()[GetParam()].variant;
    const BoardConfig config = v.board();
    const auto capacity = static_cast<uint32_t>(v.capacity());
    BoardCore lockstep(config, capacity, Fidelity::kLockstep);
    std::mt19937 rng(2024 + v.m);
    uint32_t scenes = 0, frames = 0, pauses = 0;
    uint64_t stalls = 0;
    for (uint32_t n : sizes_for(v)) {
        for (float density : {0.5f, 4.0f}) {
            // Three frames: the first uploads everything, the others only what moved.
            const float extent = std::cbrt(static_cast<float>(n)) * 10.0f / density;
            auto boxes = with_hard_words(random_boxes(n, extent, 3.0f, rng), rng);
            for (int frame = 0; frame < 3; ++frame) {
                SCOPED_TRACE(v.spec() + ": N " + std::to_string(n) + ", density " + std::to_string(density) +
                             ", frame " + std::to_string(frame));
                BoardCore clocked(config, capacity, Fidelity::kCycle);
                const CoreRun expected = run_core(clocked, boxes);
                const CoreRun got = run_core(lockstep, boxes);
                ASSERT_EQ(lockstep.engine().divergence(), "");
                EXPECT_EQ(expected.pairs, got.pairs);
                EXPECT_EQ(expected.cycles, got.cycles);
                EXPECT_EQ(expected.stalls, got.stalls);
                EXPECT_EQ(expected.pauses, got.pauses);
                pauses += got.pauses;
                stalls += got.stalls;
                ++frames;
                for (std::size_t i = frame; i < boxes.size(); i += 3) boxes[i].max[0] += 0.75f;
            }
            ++scenes;
        }
    }
    const auto& engine = dynamic_cast<LockstepEngine&>(lockstep.engine());
    std::cout << "lockstep " << v.spec() << ": " << scenes << " scenes, " << frames << " frames, "
              << engine.edges_compared() << " edges compared, " << stalls << " stall cycles, " << pauses
              << " pauses\n";
    EXPECT_GT(engine.edges_compared(), 0u);
}

std::string variant_name(const ::testing::TestParamInfo<std::size_t>& info) {
    std::string name = built_rtl_variants()[info.param].variant.spec();
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

std::vector<std::size_t> variant_indices() {
    std::vector<std::size_t> indices(built_rtl_variants().size());
    for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = k;
    return indices;
}

INSTANTIATE_TEST_SUITE_P(BuiltVariants, RtlLockstep, ::testing::ValuesIn(variant_indices()), variant_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(RtlLockstep);

// The check itself: a model whose compare pipeline is one stage shorter than
// the RTL's must stop at the first edge where the model pushes hits the RTL
// has not computed yet, naming that signal.
TEST(RtlLockstepCheck, StopsAtTheFirstDifferenceWithItsCycleAndSignal) {
    const BuiltRtlVariant* built = nullptr;
    for (const BuiltRtlVariant& b : built_rtl_variants()) {
        if (b.variant.compare_latency >= 1 && b.variant.tile_boxes == 0 && !b.variant.grid) built = &b;
    }
    ASSERT_NE(built, nullptr) << "no block RAM variant with a piped compare is built";
    const BoardConfig rtl = built->variant.board();
    BoardConfig model = rtl;
    model.compare.latency_cycles -= 1;
    std::mt19937 rng(7);
    const auto boxes = random_boxes(64, 8.0f, 3.0f, rng);
    const CoordinateStore store = testing::float32_store(boxes);
    // The model's first edge with hits.
    ClockedEngine alone(model, 64);
    alone.start(store, 64);
    uint64_t first_hits = 0;
    while (first_hits == 0) {
        alone.advance_to(alone.edges() + 1);
        ASSERT_EQ(alone.state(), SweepState::kRunning) << "the scene has no pairs";
        if (alone.pushed_hits() != 0) first_hits = alone.edges();
    }
    LockstepEngine lockstep(model, rtl, static_cast<uint32_t>(built->variant.capacity()));
    lockstep.start(store, 64);
    const uint64_t edges = lockstep.segment_edges();
    const LockstepDivergence* divergence = lockstep.first_divergence();
    ASSERT_NE(divergence, nullptr) << "the lockstep check missed a model one compare stage short";
    EXPECT_EQ(divergence->signal(), "lane_hits_pushed") << divergence->what();
    EXPECT_EQ(divergence->cycle(), first_hits) << divergence->what();
    EXPECT_NE(std::string(divergence->what()).find("cycle " + std::to_string(first_hits)), std::string::npos);
    EXPECT_EQ(lockstep.divergence(), divergence->what());
    // Past the difference the RTL goes on alone and ends its segment as it would unchecked.
    RtlEngine alone_rtl(rtl, static_cast<uint32_t>(built->variant.capacity()));
    alone_rtl.start(store, 64);
    EXPECT_EQ(edges, alone_rtl.segment_edges());
    EXPECT_EQ(lockstep.counters_after(edges).total_pairs, alone_rtl.counters_after(edges).total_pairs);
}

// What the RTL cannot run at all is refused in one line saying why, before
// any model is looked for (a board any variant could serve compiles one).
TEST(RtlVariants, ABoardTheRtlCannotRunIsRefusedSayingWhy) {
    BoardConfig two_banks, fast_drain, slow_tiles, grid;
    two_banks.box_banks = 2;
    grid.algorithm = BoardAlgorithm::kGrid;  // its top reads a box a slot (docs/grid_board.md)
    grid.tiles.cycles_per_box = 3;
    fast_drain.collector.drain_per_cycle = 4;
    slow_tiles.tiles.boxes = 64;
    slow_tiles.tiles.cycles_per_box = 2;
    const std::pair<BoardConfig, const char*> refused[] = {
        {two_banks, "one box bank"}, {fast_drain, "one pair a cycle"}, {slow_tiles, "in one cycle"},
        {grid, "the grid board RTL reads a box from six SSRAM banks in one slot"}};
    for (const auto& [config, why] : refused) {
        EXPECT_NE(rtl_unsupported(config).find(why), std::string::npos) << why;
        try {
            rtl_variant_for(config, 300);
            ADD_FAILURE() << "the RTL cannot run a board with " << why;
        } catch (const std::invalid_argument& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind("fidelity rtl: ", 0), 0u) << what;
            EXPECT_NE(what.find(why), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
    EXPECT_EQ(rtl_unsupported(BoardConfig{}), "");
}

// A variant's name and Verilator parameters follow its spec, as the CMake
// list's built-in variants spell them.
TEST(RtlVariants, NameAndParametersFollowTheSpec) {
    BoardConfig config;
    config.m = 3;
    config.format = NumberFormat::fixed(12);
    config.compare.latency_cycles = 1;
    config.collector.fifo_depth = 16;
    config.collector.buffer_depth = 32;
    config.tiles.boxes = 32;
    config.tiles.load_latency_cycles = 0;
    const RtlVariant v = RtlVariant::for_board(config, 300);
    EXPECT_EQ(v.spec(), "m=3,format=fixed12,latency=1,fifo=16,buffer=32,tile=32,tile_latency=0,capacity=512");
    EXPECT_EQ(v.name(), "m3_fixed12_l1_f16_b32_t32_s0_a9");
    EXPECT_EQ(v.verilator_parameters(),
              (std::vector<std::string>{"-GM=3", "-GAW=9", "-GFLOAT=0", "-GWIDTH=12", "-GCOMPARE_LATENCY=1",
                                        "-GFIFO_DEPTH=16", "-GBUFFER_DEPTH=32", "-GTILE_BOXES=32", "-GTILE_LATENCY=0"}));
    config.format = NumberFormat::float32();
    EXPECT_EQ(RtlVariant::for_board(config, 16).verilator_parameters()[2], "-GFLOAT=1");
    EXPECT_EQ(RtlVariant::for_board(config, 16).verilator_parameters()[3], "-GWIDTH=32");
}

TEST(RtlVariants, EachServesItsOwnBoardAndNoLargerOne) {
    ASSERT_FALSE(built_rtl_variants().empty());
    for (const BuiltRtlVariant& b : built_rtl_variants()) {
        const auto capacity = static_cast<uint32_t>(b.variant.capacity());
        EXPECT_TRUE(b.variant.serves(b.variant.board(), capacity)) << b.variant.spec();
        EXPECT_TRUE(b.variant.serves(b.variant.board(), capacity / 2 + 1)) << b.variant.spec();
        EXPECT_FALSE(b.variant.serves(b.variant.board(), capacity + 1)) << b.variant.spec();
        EXPECT_EQ(RtlVariant::for_board(b.variant.board(), capacity).spec(), b.variant.spec());
    }
}

}  // namespace
}  // namespace cdvp
