// The board's block RAM energy from its memories' geometry (docs/energy.md):
// a cycle charges the blocks it enables, one of each cascade, so the memory
// term is what it always was up to one block deep (512 float32 boxes), flat
// in N beyond, and grows with the copies m.
#include "platform/frame_energy.h"

#include <gtest/gtest.h>

#include "models/board_spec/board_config.h"

namespace cdvp {
namespace {

constexpr double kBlockRamPj = 23;  // alveo-u250's figure, pJ a block RAM a cycle

BoardConfig all_pairs(uint32_t m) {
    BoardConfig b;
    b.m = m;
    return b;
}

// The device fit's memories for `boxes` boxes on `board` (no pair FIFO in block RAM).
BoardResources fit_of(const BoardConfig& board, uint64_t boxes) {
    BoardResources fit;
    fit.coordinate_memories.block_rams = double(board.block_rams(boxes));
    fit.memory_geometry = board.block_ram_geometry(boxes);
    return fit;
}

// A frame of `boxes` boxes on `board`: its sweep's cycles, its upload's bytes.
FramePhases sweep_of(const BoardConfig& board, uint64_t boxes) {
    FramePhases p;
    p.total_ns = 1e6;
    p.compute_cycles = board.sweep_cycles(boxes);
    p.upload_bytes = 24 * boxes;
    return p;
}

// The frame's energy with block RAM the only power drawn: its memory term.
FrameEnergy memory_only(const BoardResources& fit, const FramePhases& phases) {
    PowerCoefficients power;
    power.block_ram_uw_per_mhz = kBlockRamPj;
    return board_frame_energy(power, fit.total(), frame_activity(phases, 32, WaitMode::kPoll, fit));
}
FrameEnergy memory_only(const BoardConfig& board, uint64_t boxes, const FramePhases& phases) {
    return memory_only(fit_of(board, boxes), phases);
}

// Joules a compare cycle of `boxes` boxes costs in block RAM.
double per_compare_cycle_j(const BoardConfig& board, uint64_t boxes) {
    FramePhases p;
    p.total_ns = 1e6;
    p.compute_cycles = 1000;
    return memory_only(board, boxes, p).dynamic_j / 1000;
}

TEST(BlockRamEnergy, UpToOneBlockDeepEveryBlockTheMemoriesHoldIsChargedEveryCycleAsBefore) {
    for (uint32_t m : {1u, 8u, 32u}) {
        for (uint64_t boxes : {64u, 300u, 512u}) {
            const BoardConfig board = all_pairs(m);
            const FramePhases p = sweep_of(board, boxes);
            const FrameActivity a = frame_activity(p, 32, WaitMode::kPoll, fit_of(board, boxes));
            // Every block held, on every compare and every write cycle.
            const double held = double(board.block_rams(boxes));
            EXPECT_DOUBLE_EQ(memory_only(board, boxes, p).dynamic_j,
                             held * kBlockRamPj * double(a.active_cycles + a.memory_write_cycles) * 1e-12)
                << "m = " << m << ", " << boxes << " boxes";
        }
    }
}

TEST(BlockRamEnergy, BeyondOneBlockACycleCostsTheSameWhateverTheDepth) {
    const BoardConfig board = all_pairs(32);
    const double one_block = per_compare_cycle_j(board, 512);
    EXPECT_DOUBLE_EQ(one_block, 32 * 6 * kBlockRamPj * 1e-12);
    for (uint64_t boxes : {513u, 1024u, 3200u, 10000u}) {
        EXPECT_DOUBLE_EQ(per_compare_cycle_j(board, boxes), one_block) << boxes << " boxes";
    }
    // An upload write cycle enables every copy of one depth block, at any depth.
    EXPECT_EQ(board.block_ram_geometry(3200).write_enabled(), board.block_ram_geometry(512).write_enabled());
}

TEST(BlockRamEnergy, ChargesFarLessThanEveryBlockHeldOnceTheMemoriesCascade) {
    // 3,200 boxes at m = 32: 1,344 blocks held, seven deep; 192 enabled a cycle.
    const BoardConfig board = all_pairs(32);
    const FramePhases p = sweep_of(board, 3200);
    const FrameActivity a = frame_activity(p, 32, WaitMode::kPoll, fit_of(board, 3200));
    ASSERT_EQ(board.block_rams(3200), 1344u);
    const double every_block_held =
        1344 * kBlockRamPj * double(a.active_cycles + a.memory_write_cycles) * 1e-12;
    const double charged = memory_only(board, 3200, p).dynamic_j;
    EXPECT_DOUBLE_EQ(charged, 192 * kBlockRamPj * double(a.active_cycles + a.memory_write_cycles) * 1e-12);
    EXPECT_NEAR(every_block_held / charged, 7.0, 1e-12);
}

TEST(BlockRamEnergy, ACycleEnablesBlocksInProportionToTheCopiesM) {
    for (uint64_t boxes : {300u, 3200u}) {
        const double at_8 = per_compare_cycle_j(all_pairs(8), boxes);
        EXPECT_DOUBLE_EQ(per_compare_cycle_j(all_pairs(16), boxes), 2 * at_8) << boxes << " boxes";
        EXPECT_DOUBLE_EQ(per_compare_cycle_j(all_pairs(32), boxes), 4 * at_8) << boxes << " boxes";
    }
}

TEST(BlockRamEnergy, NarrowFormatsEnableTheirFewerWordGroups) {
    // fixed16 packs a box's six coordinates in three 1K x 18 primitives' worth: three word groups.
    BoardConfig board = all_pairs(8);
    board.format = NumberFormat::fixed(16);
    const BlockRamGeometry g = board.block_ram_geometry(3200);
    EXPECT_EQ(g.word_groups * g.depth_blocks * g.copies, board.block_rams(3200));
    EXPECT_EQ(g.read_enabled(), 8 * g.word_groups);
    EXPECT_LT(g.read_enabled(), board.block_rams(3200));
}

TEST(BlockRamEnergy, TwoBoxBanksSweepOneAndTakeTheUploadInTheOther) {
    BoardConfig board = all_pairs(8);
    board.box_banks = 2;
    const BlockRamGeometry g = board.block_ram_geometry(300);
    EXPECT_EQ(board.block_rams(300), 2 * 8 * 6u);
    EXPECT_EQ(g.read_enabled(), 8 * 6u);
    EXPECT_EQ(g.write_enabled(), 8 * 6u);
}

TEST(BlockRamEnergy, TiledAndGridBoardsEnableBothBuffersAndTakeNoUploadInBlockRam) {
    // Tiles of 256 boxes in SSRAM: both tile buffers (2m + 2 copies) are read each cycle.
    BoardConfig tiled = all_pairs(8);
    tiled.tiles.boxes = 256;
    const BlockRamGeometry t = tiled.block_ram_geometry(10000);
    EXPECT_EQ(t.read_enabled(), tiled.block_rams(10000));
    EXPECT_EQ(t.read_enabled(), (2 * 8 + 2) * 6u);
    EXPECT_EQ(t.write_enabled(), 0u);
    // The grid board's cell buffer: two halves of m copies, C boxes deep.
    BoardConfig grid = all_pairs(8);
    grid.algorithm = BoardAlgorithm::kGrid;
    grid.grid.cell_capacity = 2048;
    const BlockRamGeometry c = grid.block_ram_geometry(10000);
    EXPECT_EQ(grid.block_rams(10000), 2 * 8 * 6 * 4u);
    EXPECT_EQ(c.read_enabled(), 2 * 8 * 6u);
    EXPECT_EQ(c.write_enabled(), 0u);
    grid.grid.cell_capacity = 512;
    EXPECT_EQ(grid.block_ram_geometry(10000).read_enabled(), c.read_enabled());
}

TEST(BlockRamEnergy, ThePartsStillAddUp) {
    PowerCoefficients power;
    power.static_w = 4;
    power.clb_uw_per_mhz = 0.47;
    power.block_ram_uw_per_mhz = kBlockRamPj;
    power.io_pj_per_toggle = 3.6;
    power.bus_w = 5;
    power.host_w = 7.5;
    power.host_idle_w = 1.9;
    const BoardConfig board = all_pairs(32);
    FramePhases p = sweep_of(board, 3200);
    p.upload_ns = 20000;
    p.compute_ns = 300000;
    p.readback_ns = 10000;
    p.readback_bytes = 8000;
    BoardResources fit = fit_of(board, 3200);
    fit.lanes.luts = 100000;
    fit.lanes.flip_flops = 50000;
    fit.pair_collector.block_rams = 1;
    const FrameEnergy e = board_frame_energy(power, fit.total(), frame_activity(p, 32, WaitMode::kIrq, fit));
    EXPECT_DOUBLE_EQ(e.total_j(), e.static_j + e.dynamic_j + e.bus_j + e.host_j);
    EXPECT_GT(e.dynamic_j, memory_only(board, 3200, p).dynamic_j);  // logic and I/O beside the memories
}

// The pair FIFO's block RAM is written and read as the lanes find pairs:
// charged on compare cycles, not on the upload's.
TEST(BlockRamEnergy, APairFifoInBlockRamIsChargedOnCompareCyclesOnly) {
    const BoardConfig board = all_pairs(8);
    const FramePhases p = sweep_of(board, 300);
    BoardResources fit = fit_of(board, 300);
    const double without = memory_only(fit, p).dynamic_j;
    fit.pair_collector.block_rams = 1;
    const FrameActivity a = frame_activity(p, 32, WaitMode::kPoll, fit);
    EXPECT_DOUBLE_EQ(a.block_rams_read, 8 * 6 + 1);
    EXPECT_DOUBLE_EQ(a.block_rams_written, 8 * 6);
    EXPECT_NEAR(memory_only(fit, p).dynamic_j - without, kBlockRamPj * double(a.active_cycles) * 1e-12, 1e-18);
}

}  // namespace
}  // namespace cdvp
