// The whole-board timing table (scripts/timing.sh --board-row,
// models/resources/whole_board_timing.csv): its parser, its lookup (the
// slower neighbouring m, the narrowest address width that holds the boxes,
// none for a tiled board), the board's Fmax as the lesser of it and the
// pieces', and what the stored rows say of the RTL.
#include "models/resources/whole_board_timing.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace cdvp {
namespace {

const std::string kWholeHeader =
    "family,board,format,m,latency,fifo,address_bits,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to\n";

// Two m at 9 address bits, one at 12, and a LUT FIFO's and a grid board's row.
WholeBoardTable small_whole_table() {
    return WholeBoardTable::parse(kWholeHeader +
                                      "xc2v,all_pairs,float32,1,2,block_ram,9,4,12.0,4,20,0,flip_flop,flip_flop\n"
                                      "xc2v,all_pairs,float32,8,2,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"
                                      "xc2v,all_pairs,float32,8,2,block_ram,12,4,13.0,6,24,2,flip_flop,flip_flop\n"
                                      "xc2v,all_pairs,float32,8,2,distributed,9,4,15.0,6,20,2,lut_ram,flip_flop\n"
                                      "xc2v,grid,float32,8,2,block_ram,9,4,90.0,20,60,4,flip_flop,flip_flop\n",
                                  "small.csv");
}

// The pieces of an all-pairs and a grid board, each faster than the whole board's rows.
TimingTable pieces_beside_whole() {
    return TimingTable::parse(
        "family,piece,format,m,latency,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to\n"
        "xc2v,board_control,-,-,-,4,5.0,1,30,0,flip_flop,flip_flop\n"
        "xc2v,compare_lane,float32,-,2,4,9.0,4,16,0,block_ram,flip_flop\n"
        "xc2v,address_generator,-,1,-,4,4.0,2,10,0,flip_flop,flip_flop\n"
        "xc2v,address_generator,-,8,-,4,4.0,2,10,0,flip_flop,flip_flop\n"
        "xc2v,tile_walker,-,1,-,4,8.0,5,20,0,flip_flop,flip_flop\n"
        "xc2v,tile_walker,-,8,-,4,8.0,5,20,0,flip_flop,flip_flop\n"
        "xc2v,pair_collector,block_ram,1,2,4,9.5,6,0,4,block_ram,flip_flop\n"
        "xc2v,pair_collector,block_ram,8,2,4,10.5,7,0,6,block_ram,flip_flop\n"
        "xc2v,pair_collector,block_ram,1,-,4,9.5,6,0,4,block_ram,flip_flop\n"
        "xc2v,pair_collector,block_ram,8,-,4,10.5,7,0,6,block_ram,flip_flop\n"
        "xc2v,home_cell_filter,-,8,-,4,4.0,3,0,0,flip_flop,flip_flop\n"
        "xc2v,grid_cell_function,float32,-,-,4,30.0,6,20,0,flip_flop,flip_flop\n"
        "xc2v,cell_loader,float32,-,-,4,7.0,4,20,0,flip_flop,block_ram\n"
        "xc2v,grid_sequencer,float32,8,-,4,40.0,30,50,4,flip_flop,flip_flop\n",
        "pieces.csv");
}

std::string whole_parse_error(const std::string& row) {
    try {
        WholeBoardTable::parse(kWholeHeader + row, "w.csv");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(WholeBoardTable, RefusesAMalformedRowNamingTheLineAndColumn) {
    EXPECT_EQ(whole_parse_error(""), "");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8,2,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"), "");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8\n"), "w.csv:2: expected 14 fields, got 4");
    EXPECT_EQ(whole_parse_error("xc2v,tiled,float32,8,2,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: board: expected all_pairs or grid, got 'tiled'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,fixed,8,2,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: format: expected float32 or fixed1 to fixed64, got 'fixed'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,fixed65,8,2,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: format: expected float32 or fixed1 to fixed64, got 'fixed65'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,-,2,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: m: expected 1 or more, got '-'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8,two,block_ram,9,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: latency: expected a whole number or '-', got 'two'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8,2,lut,9,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: fifo: expected block_ram or distributed, got 'lut'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8,2,block_ram,40,4,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: address_bits: expected 1 to 32, got '40'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8,2,block_ram,9,-,11.0,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: speed_grade: expected a grade, got '-'");
    EXPECT_EQ(whole_parse_error("xc2v,all_pairs,float32,8,2,block_ram,9,4,-3,6,20,2,flip_flop,flip_flop\n"),
              "w.csv:2: path_ns: expected a positive number of ns, got '-3'");
    EXPECT_EQ(whole_parse_error("\nxc2v,all_pairs,float32,8,2,block_ram,9,4,11.0,6,20,2,flip_flop,latch\n"),
              "w.csv:3: to: expected flip_flop, block_ram or lut_ram, got 'latch'");
    try {
        WholeBoardTable::parse("family,piece,format\n", "w.csv");
        ADD_FAILURE() << "a piece table's header taken";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()).rfind("w.csv:1: expected the header family,board,format,m,", 0), 0u) << e.what();
    }
}

TEST(WholeBoardTable, TakesTheSlowerNeighbourAndTheNarrowestWidthThatHoldsTheBoxes) {
    const WholeBoardTable table = small_whole_table();
    TimedBoard board{"xc2v", 4, "float32", 8, 2, FifoMemory::kBlockRam, false, false, 9};
    EXPECT_DOUBLE_EQ(table.path(board).path->ns, 11.0);
    board.m = 4;  // between m = 1 (12 ns) and 8 (11 ns): the slower
    EXPECT_DOUBLE_EQ(table.path(board).path->ns, 12.0);
    board.m = 8;
    board.address_bits = 8;  // 256 boxes: the 9-bit row holds them
    EXPECT_DOUBLE_EQ(table.path(board).path->ns, 11.0);
    board.address_bits = 10;  // 1,024 boxes: the 12-bit row
    EXPECT_DOUBLE_EQ(table.path(board).path->ns, 13.0);
    board.address_bits = 13;
    EXPECT_EQ(table.path(board).path, std::nullopt);
    EXPECT_EQ(table.path(board).missing,
              "no whole-board timing of the all-pairs board (xc2v -4, float32, compare latency 2, pair FIFO in block "
              "RAM, 13 address bits) stored around m = 8");
    board.address_bits = 9;
    board.fifo_memory = FifoMemory::kDistributed;
    EXPECT_EQ(table.path(board).path->from, "lut_ram");
    board.m = 4;  // the LUT FIFO's rows have no m below 8
    EXPECT_EQ(table.path(board).path, std::nullopt);
    board = {"xc2v", 4, "float32", 8, 1, FifoMemory::kBlockRam, false, false, 9};  // another compare latency
    EXPECT_EQ(table.path(board).path, std::nullopt);
    board = {"xc2v", 5, "float32", 8, 2, FifoMemory::kBlockRam, false, false, 9};  // another grade
    EXPECT_EQ(table.path(board).path, std::nullopt);
    board = {"xc2v", 4, "fixed16", 8, 2, FifoMemory::kBlockRam, false, false, 9};  // another format
    EXPECT_EQ(table.path(board).path, std::nullopt);
    board = {"xc2v", 4, "float32", 8, 2, FifoMemory::kBlockRam, true, false, 9};
    EXPECT_EQ(table.path(board).missing, "no whole-board timing of the all-pairs board with its boxes in SSRAM tiles");
    board = {"xc2v", 4, "float32", 8, 2, FifoMemory::kBlockRam, false, true, 9};
    EXPECT_DOUBLE_EQ(table.path(board).path->ns, 90.0);
}

TEST(WholeBoardTable, TheBoardsFmaxIsTheLesserOfTheWholeBoardAndItsPieces) {
    const WholeBoardTable whole = small_whole_table();
    TimedBoard board{"xc2v", 4, "float32", 8, 2, FifoMemory::kBlockRam, false, false, 9};
    BoardTiming timing = board_timing(pieces_beside_whole(), whole, board);
    // The whole board (11 ns) is slower than its slowest piece, the FIFO (10.5 ns).
    EXPECT_EQ(timing.limiting().key, "whole_board");
    EXPECT_EQ(timing.limiting().piece,
              "whole board as one design (longest path: flip-flop to flip-flop through 6 LUTs, 20 carry cells and 2 "
              "wide multiplexers)");
    EXPECT_DOUBLE_EQ(timing.fmax_mhz(), 1e3 / 11.0);
    EXPECT_EQ(timing.whole_board_missing, "");
    // With no row, the pieces alone, and why.
    board.address_bits = 13;
    timing = board_timing(pieces_beside_whole(), whole, board);
    EXPECT_EQ(timing.limiting().key, "pair_fifo");
    EXPECT_DOUBLE_EQ(timing.fmax_mhz(), 1e3 / 10.5);
    EXPECT_NE(timing.whole_board_missing.find("13 address bits"), std::string::npos) << timing.whole_board_missing;
    // The grid board's whole path runs through the pieces awaiting their
    // pipelining: reported beside them until they are, then held to.
    board = {"xc2v", 4, "float32", 8, 2, FifoMemory::kBlockRam, false, true, 9};
    timing = board_timing(pieces_beside_whole(), whole, board);
    const std::vector<PieceTiming>& whole_list = kGridPiecesAwaitPipelining ? timing.awaiting_pipelining : timing.pieces;
    ASSERT_FALSE(whole_list.empty());
    EXPECT_EQ(whole_list.back().key, "whole_board");
    EXPECT_DOUBLE_EQ(timing.slowest().path.ns, 90.0);
    // Until then the lane (9 ns) limits it; the FIFO behind the one-cell filter waits with them.
    EXPECT_DOUBLE_EQ(timing.fmax_mhz(), kGridPiecesAwaitPipelining ? 1e3 / 9.0 : 1e3 / 90.0);
}

// What the stored rows say: every row's family and grade are the piece
// table's, a faster grade is faster on every stored design, and the whole
// board is no faster than the slowest piece the piece table gives it.
TEST(StoredWholeBoardTiming, FasterGradesAreFasterAndTheWholeIsNoFasterThanItsPieces) {
    const TimingTable& pieces = TimingTable::stored();
    const WholeBoardTable& whole = WholeBoardTable::stored();
    int timed = 0;
    for (const std::string family : {"xc2v", "xcup"}) {
        const std::vector<uint32_t> grades = pieces.speed_grades(family);
        for (const std::string format : {"float32", "fixed16"}) {
            for (uint32_t m = 1; m <= 32; ++m) {
                double slower_grade_ns = 0;
                for (const uint32_t grade : grades) {
                    const TimedBoard board{family, grade, format, m, 2, FifoMemory::kBlockRam, false, false, 9};
                    const WholeBoardPath path = whole.path(board);
                    if (!path.path) continue;
                    ++timed;
                    const std::string what = family + " -" + std::to_string(grade) + " " + format + " m = " +
                                             std::to_string(m);
                    if (slower_grade_ns > 0) {
                        EXPECT_LT(path.path->ns, slower_grade_ns) << what;
                    }
                    slower_grade_ns = path.path->ns;
                    BoardTiming alone = board_timing(pieces, WholeBoardTable::parse(kWholeHeader, "none.csv"), board);
                    EXPECT_GE(path.path->ns, 0.9 * alone.limiting().path.ns) << what;
                }
            }
        }
    }
    // Both families' paper and card presets at their default m = 8, float32, are stored.
    EXPECT_GT(timed, 0);
    for (const auto& [family, grade] : {std::pair<std::string, uint32_t>{"xc2v", 4}, {"xcup", 1}, {"xcup", 2}}) {
        const TimedBoard board{family, grade, "float32", 8, 2, FifoMemory::kBlockRam, false, false, 9};
        EXPECT_TRUE(whole.path(board).path.has_value()) << family << " -" << grade;
    }
}

}  // namespace
}  // namespace cdvp
