// Where a run's board keeps its boxes: board.memory, board.tile_boxes and the
// device's block RAMs and SSRAM.
#include "platform/memory_plan.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

Settings on_device(uint32_t block_rams, uint32_t m) {
    Settings s;
    s.device.block_rams = block_rams;
    s.board.m = m;
    return s;
}

// The auto tile fills the block RAMs a primitive (512 boxes) at a time:
// 6 x (2m+2) x ceil(T/512) <= block RAMs.
TEST(MemoryPlan, TheAutoTileIsTheLargestWhoseBuffersFit) {
    EXPECT_EQ(largest_tile(on_device(144, 8).board, 65536, 144), 512u);     // 108 of 144
    EXPECT_EQ(largest_tile(on_device(144, 11).board, 65536, 144), 512u);    // 144 of 144
    EXPECT_EQ(largest_tile(on_device(144, 12).board, 65536, 144), 0u);      // 156: none
    EXPECT_EQ(largest_tile(on_device(4320, 8).board, 65536, 4320), 20480u);  // 40 primitives
    EXPECT_EQ(largest_tile(on_device(4320, 32).board, 65536, 4320), 5120u);  // 10 primitives
    EXPECT_EQ(largest_tile(on_device(4320, 8).board, 3000, 4320), 3000u);    // one tile holds all
    EXPECT_EQ(largest_tile(on_device(0, 8).board, 3000, 0), 3000u);          // unbounded
}

TEST(MemoryPlan, AutoKeepsBlockRamWhileItFitsThenTiles) {
    Settings s = on_device(144, 8);
    EXPECT_FALSE(plan_memory(s, 512).ssram);  // 48 block RAMs
    const MemoryPlan past = plan_memory(s, 2000);  // 6 x 8 x 4 = 192 > 144
    EXPECT_TRUE(past.ssram);
    EXPECT_EQ(past.tiles.boxes, 512u);
    EXPECT_EQ(past.ssram_capacity, 524288u);
    s.run.ignore_capacity = true;
    EXPECT_FALSE(plan_memory(s, 2000).ssram) << "exploring a larger device keeps block RAM";
    s = on_device(144, 24);
    EXPECT_FALSE(plan_memory(s, 2000).ssram) << "no tile fits at m = 24: block RAM, refused as before";
    s.memory.memory = BoxMemory::kSsram;
    EXPECT_TRUE(plan_memory(s, 2000).ssram);
    EXPECT_FALSE(plan_memory(s, 2000).tile_fits);
}

TEST(MemoryPlan, AskedMemoryAndTilesAreTakenAsGiven) {
    Settings s = on_device(144, 8);
    s.memory.memory = BoxMemory::kSsram;
    s.memory.tile_boxes = 64;
    const MemoryPlan plan = plan_memory(s, 300);
    EXPECT_TRUE(plan.ssram);
    EXPECT_EQ(plan.tiles.boxes, 64u);
    EXPECT_EQ(planned_board(s, 300).block_rams(300), 6u * 18 * 1);
    s.device.ssram_banks = 4;  // two cycles a box, half the boxes
    EXPECT_EQ(plan_memory(s, 300).tiles.cycles_per_box, 2u);
    EXPECT_EQ(plan_memory(s, 300).ssram_capacity, 262144u);
    s.memory.memory = BoxMemory::kBlockRam;
    EXPECT_FALSE(plan_memory(s, 300).ssram);
    EXPECT_EQ(planned_board(s, 300).tiles.boxes, 0u);
}

}  // namespace
}  // namespace cdvp
