// The grid board assembled: BoardCore's registers on a grid board, its pairs
// through the pair buffer's pauses, and the seed's board left as it was.
#include <gtest/gtest.h>

#include <random>

#include "models/board/board_core.h"
#include "models/board/engine_factory.h"
#include "tests/fast_engine/word_scenes.h"
#include "tests/support/core_driver.h"

namespace cdvp {
namespace {

using R = ControlRegisters;

BoardConfig grid_board_config(uint32_t buffer = 262144) {
    BoardConfig config;
    config.m = 4;
    config.algorithm = BoardAlgorithm::kGrid;
    config.collector.fifo_depth = 7;
    config.collector.buffer_depth = buffer;
    config.grid.cell_capacity = 64;
    config.grid.entry_capacity = 100000;
    config.tiles.load_latency_cycles = 3;
    config.tiles.cycles_per_box = 2;
    return config;
}

TEST(GridBoard, ItsPairsPassThePairBuffersPausesWhole) {
    std::mt19937 rng(11);
    const std::vector<FloatBox> boxes = testing::random_boxes(2500, 30.0f, 3.0f, rng);
    for (uint32_t buffer : {1u, 13u, 262144u}) {
        BoardCore core(grid_board_config(buffer), 3000, Fidelity::kFast);
        const testing::CoreRun run = testing::run_core(core, boxes);
        EXPECT_EQ(testing::lane_hit_pairs(testing::WordScene::from_boxes(boxes)), sorted(run.pairs)) << buffer;
        EXPECT_EQ(run.pairs.size(), core.counters().total_pairs);
        if (buffer < 100) {
            EXPECT_GE(run.pauses, run.pairs.size() / buffer - 1) << buffer;
        }
        // Every edge is a slot, the pipeline's latency or a stall.
        EXPECT_EQ(core.engine().grid_stats().slots + core.config().pipeline_latency() + run.stalls, run.cycles);
    }
}

TEST(GridBoard, AnswersItsIdAndGridRegisters) {
    std::mt19937 rng(12);
    BoardConfig config = grid_board_config();
    config.grid.cell_size = 2.5f;
    config.grid.dims = 9;
    BoardCore core(config, 1000, Fidelity::kFast);
    EXPECT_EQ(R::kGridIdValue, testing::read_register(core, R::kId));
    EXPECT_EQ(9u, testing::read_register(core, R::kGridDims));
    EXPECT_EQ(64u, testing::read_register(core, R::kGridCellCapacity));
    EXPECT_EQ(8u, testing::read_register(core, R::kGridMaxSpan));
    EXPECT_EQ(0x4020'0000u, testing::read_register(core, R::kGridCellSize)) << "2.5f";
    EXPECT_EQ(100000u, testing::read_register(core, R::kGridEntryCapacity));
    EXPECT_EQ(3u | 2u << R::kTileTimingCyclesShift, testing::read_register(core, R::kTileTiming));
    EXPECT_EQ(0u, testing::read_register(core, R::kTileBoxes));
    EXPECT_EQ(0u, testing::read_register(core, R::kGridSweepDims)) << "no sweep yet";
    std::vector<FloatBox> boxes = testing::random_boxes(900, 20.0f, 2.0f, rng);
    boxes.push_back({{-1e3f, -1e3f, 0.0f}, {1e3f, 1e3f, 0.5f}});  // a ground slab
    testing::run_core(core, boxes);
    const GridSweepStats stats = core.engine().grid_stats();
    EXPECT_EQ(9u, testing::read_register(core, R::kGridSweepDims));
    EXPECT_EQ(stats.large_boxes, testing::read_register(core, R::kGridLargeBoxes));
    EXPECT_GE(stats.large_boxes, 1u);
    EXPECT_EQ(stats.overflow_boxes, testing::read_register(core, R::kGridOverflowBoxes));
    EXPECT_EQ(stats.cell_entries, testing::read_register(core, R::kGridCellEntries));
    EXPECT_GT(stats.cell_entries, 900u);
    EXPECT_EQ(stats.busy_cells, testing::read_register(core, R::kGridBusyCells));
    EXPECT_GT(stats.busy_cells, 10u);
    EXPECT_EQ(0u, testing::read_register(core, R::kGridExcludedBoxes));
}

TEST(GridBoard, TheSeedsBoardKeepsItsRegisterMap) {
    BoardCore core(BoardConfig{}, 100);
    EXPECT_EQ(R::kIdValue, testing::read_register(core, R::kId));
    uint32_t value = 0;
    for (uint32_t offset = R::kGridDims; offset <= R::kGridExcludedBoxes; offset += 4) {
        EXPECT_FALSE(core.read_register(offset, value)) << "offset " << offset;
    }
    EXPECT_EQ(0u, testing::read_register(core, R::kTileTiming));
}

}  // namespace
}  // namespace cdvp
