// Every baseline against reference_pairs: same pairs, each once, first < second.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/brute_force.h"
#include "tests/baselines/exact_pairs.h"
#include "tests/baselines/scenes.h"

namespace cdvp {
namespace {

using test::Boxes;

// Pairs that pass a strict (open interval) test: fewer than the reference when
// a scene has boxes touching exactly, so the scene catches a "<" slip.
std::size_t strict_overlaps(const Boxes& boxes) {
    std::size_t count = 0;
    for (const IndexPair& p : reference_pairs(boxes)) {
        const FloatBox& a = boxes[p.first];
        const FloatBox& b = boxes[p.second];
        bool strict = true;
        for (int axis = 0; axis < 3; ++axis) {
            strict = strict && a.min[axis] < b.max[axis] && b.min[axis] < a.max[axis];
        }
        count += strict ? 1 : 0;
    }
    return count;
}

using test::expect_exact;

class BroadPhaseTest : public ::testing::TestWithParam<std::string> {
protected:
    std::unique_ptr<BroadPhase> phase_ = make_broad_phase(GetParam());
};

TEST_P(BroadPhaseTest, ReportsItsName) { EXPECT_EQ(phase_->name(), GetParam()); }

TEST_P(BroadPhaseTest, RandomScenesOfManySizes) {
    for (std::size_t n : {0, 1, 2, 3, 50, 700, 3000}) {
        auto fresh = make_broad_phase(GetParam());  // each size on a new object
        const Boxes boxes = test::random_boxes(n, static_cast<uint32_t>(n) + 11);
        const PairList want = expect_exact(*fresh, boxes, "random scene");
        if (n >= 50) {
            EXPECT_GT(want.size(), n / 4) << "the scene should have pairs";
        }
    }
}

TEST_P(BroadPhaseTest, CoherentMotionOverThirtyFrames) {
    const auto frames = test::moving_frames(400, 30, 5);
    std::size_t touching_frames = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const PairList want = expect_exact(*phase_, frames[f], "frame " + std::to_string(f));
        touching_frames += strict_overlaps(frames[f]) < want.size() ? 1 : 0;
    }
    EXPECT_EQ(touching_frames, frames.size()) << "every frame should have exact contacts";
}

TEST_P(BroadPhaseTest, ScriptedPairStartsAndStopsTouching) {
    // Only the scripted pair: its pair appears and disappears between frames.
    const auto frames = test::moving_frames(0, 30, 1);
    std::size_t changes = 0;
    bool before = false;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const bool now = !expect_exact(*phase_, frames[f], "frame " + std::to_string(f)).empty();
        changes += now != before ? 1 : 0;
        before = now;
    }
    EXPECT_GE(changes, 6u);
}

TEST_P(BroadPhaseTest, BoxCountChangesBetweenCalls) {
    uint32_t seed = 100;
    for (std::size_t n : {50, 700, 700, 50, 0, 3, 3, 1, 2, 50}) {
        expect_exact(*phase_, test::random_boxes(n, ++seed), "count change to " + std::to_string(n));
    }
}

TEST_P(BroadPhaseTest, InfiniteBoundsAndGroundSlab) {
    const Boxes boxes = test::infinite_scene();
    const PairList want = expect_exact(*phase_, boxes, "infinite scene");
    EXPECT_TRUE(std::binary_search(want.begin(), want.end(), IndexPair{0, 1}));
    EXPECT_FALSE(std::binary_search(want.begin(), want.end(), IndexPair{0, 2}));
    EXPECT_TRUE(std::binary_search(want.begin(), want.end(), IndexPair{2, 5}));
    EXPECT_TRUE(std::binary_search(want.begin(), want.end(), IndexPair{1, 6}));
}

TEST_P(BroadPhaseTest, InfiniteSlabMovingWithTheScene) {
    // The slab's top rises through the boxes; an infinite box that moves
    // exercises the incremental update paths with unbounded extents.
    auto frames = test::moving_frames(300, 30, 9);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const float top = static_cast<float>(f) * 0.5f;
        constexpr float inf = std::numeric_limits<float>::infinity();
        frames[f].push_back(FloatBox{{-inf, -inf, -inf}, {inf, top, inf}});
        expect_exact(*phase_, frames[f], "slab frame " + std::to_string(f));
    }
}

TEST_P(BroadPhaseTest, FacesEdgesAndCornersTouch) {
    for (float step : {1.0f, 0.1f, 1e-3f}) {
        const Boxes boxes = test::touching_lattice(4, step);
        const PairList want = expect_exact(*phase_, boxes, "lattice step " + std::to_string(step));
        EXPECT_EQ(want.size(), 468u);  // pairs of cells within one step on every axis
        EXPECT_EQ(strict_overlaps(boxes), 0u);
    }
}

TEST_P(BroadPhaseTest, OneUlpGapsInALargeWorld) {
    const Boxes boxes = test::near_misses(400);
    const PairList want = expect_exact(*phase_, boxes, "near misses");
    EXPECT_EQ(want.size(), 200u);
}

TEST_P(BroadPhaseTest, EveryBoxOverlapsEveryOther) {
    const Boxes boxes = test::all_overlapping(200, 3);
    EXPECT_EQ(expect_exact(*phase_, boxes, "all overlapping").size(), 200u * 199u / 2u);
    // Then coherently shrink them apart: many pairs end in one frame.
    Boxes apart = boxes;
    for (std::size_t i = 0; i < apart.size(); ++i) {
        const float x = static_cast<float>(i) * 10.0f;
        apart[i] = {{x, 0, 0}, {x + 1, 1, 1}};
    }
    EXPECT_TRUE(expect_exact(*phase_, apart, "all apart").empty());
    expect_exact(*phase_, boxes, "all overlapping again");
}

// A baseline collects no more pairs than its budget: at the budget it finds
// them all, one below it stops at the pair past it.
TEST_P(BroadPhaseTest, StopsAtItsPairBudget) {
    const Boxes boxes = test::all_overlapping(60, 3);
    const uint64_t all = 60u * 59u / 2u;
    PairList pairs;
    phase_->set_pair_budget(PairBudget(all));
    phase_->find_pairs(boxes, pairs);
    EXPECT_EQ(pairs.size(), all);
    phase_->set_pair_budget(PairBudget(all - 1));
    try {
        phase_->find_pairs(boxes, pairs);
        ADD_FAILURE() << phase_->name() << " went past its budget";
    } catch (const PairBudgetExceeded& e) {
        EXPECT_EQ(e.found(), all);
        EXPECT_EQ(e.budget(), all - 1);
        EXPECT_LE(pairs.size(), all - 1) << "the list never holds more than the budget";
    }
}

INSTANTIATE_TEST_SUITE_P(Baselines, BroadPhaseTest, ::testing::ValuesIn(broad_phase_names()),
                         [](const auto& info) { return info.param; });

TEST(SapBroadPhase, MoreBoxesThanA16BitSweepHolds) {
    // sap switches to bt32BitAxisSweep3 above 16383 boxes; a second frame moves
    // them. Only sap has a size threshold, and building Bullet's sweep takes
    // seconds at this size (each insertion sorts into every axis).
    auto sap = make_broad_phase("sap");
    for (const Boxes& boxes : test::moving_frames(17000, 2, 21)) {
        expect_exact(*sap, boxes, "17002 boxes");
    }
}

TEST(MakeBroadPhase, NamesAndWhichRunOnOneThread) {
    EXPECT_EQ(broad_phase_names(),
              (std::vector<std::string>{"sap", "dbvt", "brute", "soa", "sap_mt", "prune", "prune_mt", "hgrid",
                                        "hgrid_mt", "fcl_tree", "fcl_sap", "fcl_interval", "fcl_hash", "ode_hash",
                                        "ode_quadtree", "ode_sap"}));
    EXPECT_EQ(single_thread_broad_phase_names(),
              (std::vector<std::string>{"sap", "dbvt", "brute", "soa", "prune", "hgrid", "fcl_tree", "fcl_sap",
                                        "fcl_interval", "fcl_hash", "ode_hash", "ode_quadtree", "ode_sap"}));
    for (const std::string& name : single_thread_broad_phase_names()) EXPECT_EQ(make_broad_phase(name)->threads(), 1u);
    const std::vector<std::string> one_thread = single_thread_broad_phase_names();
    for (const std::string& name : broad_phase_names()) {
        const bool listed = std::find(one_thread.begin(), one_thread.end(), name) != one_thread.end();
        if (!listed) {
            EXPECT_EQ(make_broad_phase(name, BaselineOptions{3})->threads(), 3u) << name;
        }
    }
}

// The parallel sweep finds the same pairs whatever its threads (more threads
// than this machine has cores, too: they take turns), frame after frame.
class MultiThreaded : public ::testing::TestWithParam<std::string> {};

TEST_P(MultiThreaded, EveryThreadCountFindsTheExactPairs) {
    for (const unsigned threads : {1u, 2u, 3u, 8u}) {
        auto phase = make_broad_phase(GetParam(), BaselineOptions{threads});
        EXPECT_EQ(phase->threads(), threads);
        for (const Boxes& boxes : test::moving_frames(1500, 4, 5 + threads)) {
            expect_exact(*phase, boxes, std::to_string(threads) + " threads");
        }
    }
    EXPECT_GE(make_broad_phase(GetParam())->threads(), 1u);  // 0: this machine's cores
}

TEST_P(MultiThreaded, APairBudgetStopsItOnAnyThread) {
    auto phase = make_broad_phase(GetParam(), BaselineOptions{3});
    const Boxes boxes = test::random_boxes(700, 3);
    PairList all;
    phase->find_pairs(boxes, all);
    ASSERT_GT(all.size(), 10u);
    phase->set_pair_budget(PairBudget(all.size() - 1));
    PairList out;
    EXPECT_THROW(phase->find_pairs(boxes, out), PairBudgetExceeded);
    phase->set_pair_budget(PairBudget(all.size()));
    phase->find_pairs(boxes, out);
    EXPECT_EQ(out.size(), all.size());
}

INSTANTIATE_TEST_SUITE_P(Baselines, MultiThreaded, ::testing::Values("sap_mt", "prune_mt", "hgrid_mt"),
                         [](const auto& info) { return info.param; });

TEST(MakeBroadPhase, UnknownNameThrows) {
    try {
        make_broad_phase("nope");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(),
                     "unknown baseline 'nope'; expected one of: sap, dbvt, brute, soa, sap_mt, prune, prune_mt, hgrid, "
                     "hgrid_mt, fcl_tree, fcl_sap, fcl_interval, fcl_hash, ode_hash, ode_quadtree, ode_sap");
    }
}

}  // namespace
}  // namespace cdvp
