// The grid board's pairs against the all-pairs board's, format by format and
// scene by scene: every pair once, none added, none lost, whatever the grid,
// the cell capacity, the span and the entry memory.
#include "models/grid_fast_engine/grid_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "tests/fast_engine/word_scenes.h"

namespace cdvp {
namespace {

BoardConfig grid_board(uint32_t m = 3) {
    BoardConfig config;
    config.m = m;
    config.algorithm = BoardAlgorithm::kGrid;
    return config;
}

std::string describe(const BoardConfig& c, uint32_t n) {
    return c.format.name() + " n=" + std::to_string(n) + " m=" + std::to_string(c.m) +
           " dims=" + std::to_string(c.grid.dims) + " cell_size=" + std::to_string(c.grid.cell_size) +
           " capacity=" + std::to_string(c.grid.cell_capacity) + " span=" + std::to_string(c.grid.max_span) +
           " entries=" + std::to_string(c.grid.entry_capacity);
}

// The grid's pairs are the lane test's, each once, and come in the order of
// their slots; the stats add up.
GridSweepStats expect_all_pairs(const BoardConfig& config, const testing::WordScene& scene) {
    GridSearch search(config);
    PairList pairs;
    std::vector<uint64_t> slots;
    const uint64_t end = search.run(scene.size(), scene.view(), pairs, slots);
    const std::string where = describe(config, scene.size());
    EXPECT_EQ(pairs.size(), slots.size()) << where;
    EXPECT_TRUE(std::is_sorted(slots.begin(), slots.end())) << where;
    EXPECT_TRUE(slots.empty() || slots.back() < end) << where;
    for (const IndexPair& p : pairs) EXPECT_LT(p.first, p.second) << where;
    EXPECT_EQ(testing::lane_hit_pairs(scene, config.format), sorted(pairs)) << where;
    const GridSweepStats& stats = search.stats();
    EXPECT_EQ(end, stats.slots) << where;
    EXPECT_LE(stats.overflow_boxes, stats.large_boxes) << where;
    EXPECT_LE(stats.large_boxes + stats.excluded_boxes, scene.size()) << where;
    if (scene.size() < 2) {
        EXPECT_EQ(0u, end);
    }
    return stats;
}

TEST(GridSearch, FindsTheAllPairsBoardsPairsOnRandomScenes) {
    std::mt19937 rng(3);
    for (uint32_t n : {0u, 1u, 2u, 3u, 60u, 700u, 4000u}) {
        const auto scene = testing::random_scene(n, 2.5f * std::cbrt(static_cast<float>(n) + 1), 2.0f, rng);
        for (uint32_t m : {1u, 3u, 8u}) expect_all_pairs(grid_board(m), scene);
    }
}

TEST(GridSearch, AnyGridAnyCapacityAnySpanKeepsEveryPair) {
    std::mt19937 rng(4);
    const auto scene = testing::random_scene(1500, 30.0f, 4.0f, rng);
    for (uint32_t dims : {0u, 1u, 2u, 7u, 40u, 256u}) {
        for (uint32_t capacity : {2u, 5u, 512u}) {
            for (uint32_t span : {1u, 8u, 64u}) {
                BoardConfig config = grid_board();
                config.grid.dims = dims;
                config.grid.cell_capacity = capacity;
                config.grid.max_span = span;
                expect_all_pairs(config, scene);
            }
        }
    }
    for (float size : {1e-6f, 0.3f, 3.0f, 1e6f}) {
        BoardConfig config = grid_board();
        config.grid.dims = 16;
        config.grid.cell_size = size;
        expect_all_pairs(config, scene);
    }
    for (uint64_t entries : {0ull, 1ull, 100ull, 2000ull}) {
        BoardConfig config = grid_board();
        config.grid.entry_capacity = entries;
        const GridSweepStats stats = expect_all_pairs(config, scene);
        EXPECT_LE(stats.cell_entries, entries);
        EXPECT_GT(stats.overflow_boxes, 0u) << "entries " << entries;
    }
}

TEST(GridSearch, AllBoxesInOneCellOverflowIntoTheLargeSweep) {
    std::mt19937 rng(5);
    const auto scene = testing::overlapping_scene(1300, rng);  // every pair meets
    BoardConfig config = grid_board(4);
    config.grid.dims = 1;
    const GridSweepStats stats = expect_all_pairs(config, scene);
    EXPECT_EQ(1300u - 512u, stats.overflow_boxes);
    EXPECT_EQ(1u, stats.busy_cells);
    config.grid.dims = 0;  // auto: the boxes straddle the middle cells
    expect_all_pairs(config, scene);
}

TEST(GridSearch, BoxesSpanningManyCellsAreSweptAgainstEveryBox) {
    std::mt19937 rng(6);
    auto scene = testing::random_scene(2000, 40.0f, 2.0f, rng);
    // A ground slab, a wall and a pillar through the whole scene.
    const float slabs[3][6] = {{-1e3f, -1e3f, 0.0f, 1e3f, 1e3f, 0.5f},
                               {10.0f, -1e3f, -1e3f, 10.5f, 1e3f, 1e3f},
                               {5.0f, 5.0f, -1e3f, 6.0f, 6.0f, 1e3f}};
    for (const auto& slab : slabs) {
        for (uint32_t c = 0; c < kCoordinates; ++c) scene.words[c].push_back(ComparisonUnit::as_bits(slab[c]));
    }
    BoardConfig config = grid_board();
    config.grid.dims = 16;  // cells of 2.5 or so: each slab spans more than 8 of them
    const GridSweepStats stats = expect_all_pairs(config, scene);
    EXPECT_EQ(3u, stats.large_boxes);
    EXPECT_EQ(0u, stats.overflow_boxes);
}

TEST(GridSearch, SpecialValuesAsTheAllPairsBoardTreatsThem) {
    std::mt19937 rng(7);
    for (uint32_t n : {40u, 900u}) {
        for (double fraction : {0.02, 0.3}) {
            auto scene = testing::random_scene(n, 12.0f, 3.0f, rng);
            testing::sprinkle_special_values(scene, fraction, rng);
            const GridSweepStats stats = expect_all_pairs(grid_board(), scene);
            uint32_t nan_boxes = 0, inverted = 0;
            for (uint32_t i = 0; i < n; ++i) {
                bool nan = false, flipped = false;
                for (uint32_t c = 0; c < kCoordinates; ++c) nan |= NumberFormat::float32().excluded(scene.words[c][i]);
                for (uint32_t a = 0; a < 3 && !nan; ++a) {
                    flipped |= !NumberFormat::float32().less_equal(scene.words[a][i], scene.words[a + 3][i]);
                }
                nan_boxes += nan;
                inverted += flipped;
            }
            EXPECT_EQ(nan_boxes, stats.excluded_boxes) << "a NaN box is left out";
            EXPECT_LE(inverted, stats.large_boxes) << "an inverted box is swept against every box";
        }
    }
    expect_all_pairs(grid_board(), testing::denormal_scene(800, rng));
    expect_all_pairs(grid_board(), testing::clustered_scene(3000, 5, rng));
}

TEST(GridSearch, FixedPointFormatsKeepTheirBoardsPairs) {
    std::mt19937 rng(8);
    for (uint32_t k : {8u, 12u, 16u, 24u, 32u}) {
        BoardConfig config = grid_board();
        config.format = NumberFormat::fixed(k);
        for (double share : {0.001, 0.02, 0.3}) expect_all_pairs(config, testing::fixed_scene(1200, config.format, share, rng));
    }
}

// The board's order: busy cells ascending, then the large tiles; every
// cell's pairs by row, then column, of its index-ordered list.
TEST(GridSearch, PairsComeInTheBoardsOrder) {
    std::mt19937 rng(9);
    const auto scene = testing::random_scene(3000, 25.0f, 2.5f, rng);
    GridSearch search(grid_board());
    PairList pairs;
    std::vector<uint64_t> slots;
    search.run(scene.size(), scene.view(), pairs, slots);
    ASSERT_GT(pairs.size(), 1000u);
    uint32_t runs = 0;  // pairs of one slot share their row box
    for (std::size_t k = 1; k < pairs.size(); ++k) {
        if (slots[k] != slots[k - 1]) continue;
        ++runs;
        EXPECT_EQ(pairs[k].first, pairs[k - 1].first);
        EXPECT_LT(pairs[k - 1].second, pairs[k].second);
    }
    EXPECT_GT(runs, 0u);
}

// The large sweep streamed as the board runs it and searched in closed
// form: the same pairs in the same order, each in the same slot, whatever
// makes boxes large (overflowing cells or entries, spanning, inverted).
TEST(GridSearch, LargeSweepSearchedAsStreamed) {
    std::mt19937 rng(11);
    struct Case {
        const char* what;
        testing::WordScene scene;
        uint32_t m, capacity, dims, span;
        uint64_t entries;
    };
    auto special = testing::random_scene(1500, 12.0f, 3.0f, rng);
    testing::sprinkle_special_values(special, 0.3, rng);
    const std::vector<Case> cases = {
        {"cells overflow", testing::random_scene(3000, 14.0f, 2.5f, rng), 3, 6, 0, 8, 1ull << 20},
        {"entries overflow", testing::random_scene(3000, 30.0f, 4.0f, rng), 8, 512, 0, 8, 700},
        {"one cell", testing::overlapping_scene(1300, rng), 4, 100, 1, 8, 1ull << 20},
        {"spanning", testing::random_scene(2000, 40.0f, 9.0f, rng), 1, 512, 40, 1, 1ull << 20},
        {"special values", special, 3, 5, 0, 8, 1ull << 20},
        {"tiles of two", testing::clustered_scene(800, 3, rng), 2, 2, 0, 8, 1ull << 20},
    };
    for (const Case& c : cases) {
        BoardConfig config = grid_board(c.m);
        config.grid.cell_capacity = c.capacity;
        config.grid.dims = c.dims;
        config.grid.max_span = c.span;
        config.grid.entry_capacity = c.entries;
        GridSearch streamed(config), searched(config);
        streamed.set_searched_above(~0u);
        searched.set_searched_above(0);
        PairList streamed_pairs, searched_pairs;
        std::vector<uint64_t> streamed_slots, searched_slots;
        const uint64_t end = streamed.run(c.scene.size(), c.scene.view(), streamed_pairs, streamed_slots);
        EXPECT_EQ(end, searched.run(c.scene.size(), c.scene.view(), searched_pairs, searched_slots)) << c.what;
        EXPECT_GT(streamed.stats().large_boxes, GridSearch::kStreamedLargeBoxes) << c.what;
        EXPECT_EQ(streamed.stats(), searched.stats()) << c.what;
        EXPECT_EQ(streamed_pairs, searched_pairs) << c.what;
        EXPECT_EQ(streamed_slots, searched_slots) << c.what;
    }
}

// The pair budget: a sweep of exactly the budget's pairs finds them all; one
// pair fewer stops at the first pair past it (cells and large tiles alike).
TEST(GridSearch, StopsAtTheFirstPairPastItsBudget) {
    std::mt19937 rng(10);
    for (uint32_t capacity : {512u, 6u, 24u}) {  // the cells alone; overflow into the large sweep, searched and streamed
        const auto scene = testing::random_scene(2000, 14.0f, 2.5f, rng);
        BoardConfig config = grid_board();
        config.grid.cell_capacity = capacity;
        PairList all, pairs;
        std::vector<uint64_t> slots;
        GridSearch(config).run(scene.size(), scene.view(), all, slots);
        ASSERT_GT(all.size(), 100u);
        GridSearch(config, PairBudget(all.size())).run(scene.size(), scene.view(), pairs, slots);
        EXPECT_EQ(pairs, all) << "capacity " << capacity;
        for (uint64_t budget : {uint64_t{0}, uint64_t{1}, all.size() / 2, all.size() - 1}) {
            try {
                GridSearch(config, PairBudget(budget)).run(scene.size(), scene.view(), pairs, slots);
                ADD_FAILURE() << "no refusal at a budget of " << budget;
            } catch (const PairBudgetExceeded& e) {
                EXPECT_EQ(e.found(), budget + 1) << "capacity " << capacity;
                EXPECT_EQ(e.budget(), budget);
            }
        }
    }
}

}  // namespace
}  // namespace cdvp
