// The pair budget in the fast engine: its search stops soon after the budget
// and never grows its lists far past it; within the budget nothing changes.
#include "models/fast_engine/pair_finder.h"

#include <gtest/gtest.h>

#include <random>

#include "models/board/board_core.h"
#include "models/fast_engine/fast_engine.h"
#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

using testing::WordScene;

// Runs `search` and returns where it stopped (0: it did not).
template <typename Search>
uint64_t stopped_at(Search&& search) {
    try {
        search();
    } catch (const PairBudgetExceeded& e) {
        return e.found();
    }
    return 0;
}

TEST(PairBudget, EitherSearchFindsEveryPairUpToItsBudgetAndStopsPastIt) {
    std::mt19937 rng(3);
    for (uint32_t n : {100u, 700u}) {  // all pairs, and the sweep
        const WordScene scene = testing::overlapping_scene(n, rng);
        const uint64_t all = uint64_t{n} * (n - 1) / 2;
        PairList pairs;
        PairFinder exact(NumberFormat::float32(), PairBudget(all));
        exact.find(scene.size(), scene.view(), pairs);
        EXPECT_EQ(pairs, testing::lane_hit_pairs(scene)) << "n=" << n;
        PairFinder short_of_it(NumberFormat::float32(), PairBudget(all - 1));
        const uint64_t found = stopped_at([&] { short_of_it.find(scene.size(), scene.view(), pairs); });
        EXPECT_GT(found, all - 1) << "n=" << n;
        EXPECT_LE(found, all) << "n=" << n;
    }
}

// 3,000 boxes that all overlap (4.5 million pairs) against a budget of 10,000:
// the sweep stops at its first check past the budget, with its lists no
// larger than the first list of blocks (a block a box) or one doubling allow.
TEST(PairBudget, TheSweepStopsAtItsFirstCheckPastTheBudget) {
    std::mt19937 rng(5);
    const uint32_t n = 3000;
    const WordScene scene = testing::overlapping_scene(n, rng);
    PairList pairs;
    for (uint64_t budget : {10'000ull, 200'000ull}) {
        PairFinder finder(NumberFormat::float32(), PairBudget(budget));
        const uint64_t found = stopped_at([&] { finder.sweep(scene.size(), scene.view(), pairs); });
        EXPECT_GT(found, budget);
        EXPECT_LE(found, 2 * budget + 4 * (n + 1)) << "budget " << budget;
        EXPECT_TRUE(pairs.empty()) << "no pairs are handed out past the budget";
    }
}

// Spread boxes meet in several cells; the budget counts each pair once.
TEST(PairBudget, APairMetInSeveralCellsCountsOnce) {
    std::mt19937 rng(8);
    const WordScene scene = testing::random_scene(20000, 80.0f, 2.0f, rng);
    PairList expected;
    PairFinder unbounded;
    unbounded.sweep(scene.size(), scene.view(), expected);
    ASSERT_GT(unbounded.last_cells(), 100u);
    PairList pairs;
    PairFinder exact(NumberFormat::float32(), PairBudget(expected.size()));
    exact.sweep(scene.size(), scene.view(), pairs);
    EXPECT_EQ(pairs, expected);
    PairFinder half(NumberFormat::float32(), PairBudget(expected.size() / 2));
    EXPECT_GT(stopped_at([&] { half.sweep(scene.size(), scene.view(), pairs); }), expected.size() / 2);
}

// The board on its fast engine refuses at START, which the host's register
// write carries back; the clocked engine keeps no more than its pair buffer.
TEST(PairBudget, TheFastBoardRefusesAtStart) {
    std::mt19937 rng(9);
    const uint32_t n = 400;
    const WordScene scene = testing::overlapping_scene(n, rng);
    BoardConfig config;
    BoardCore board(config, n, Fidelity::kFast, PairBudget(1000));
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        for (uint32_t i = 0; i < n; ++i) board.write_coordinate(static_cast<Coordinate>(c), i, scene.words[c][i]);
    }
    board.write_register(ControlRegisters::kObjectCount, n);
    EXPECT_GT(stopped_at([&] { board.write_register(ControlRegisters::kControl, ControlRegisters::kStart); }), 1000u);

    FastEngine engine(config, PairBudget(uint64_t{n} * (n - 1) / 2));
    engine.start(n, scene.view());
    EXPECT_EQ(engine.pairs().size(), uint64_t{n} * (n - 1) / 2);
}

}  // namespace
}  // namespace cdvp
