// The timing table (scripts/timing.sh, models/resources/timing.csv): its
// parser, its lookups, a board's Fmax as its slowest piece, and what the
// stored table says of the RTL: more compare stages make a faster lane,
// fixed-point lanes are faster than float32, deeper logic is slower, a
// faster speed grade is faster.
#include "models/resources/timing_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/resources/whole_board_timing.h"

namespace cdvp {
namespace {

const std::string kTimingHeader = "family,piece,format,m,latency,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to\n";

// A small table: one grade, two latencies, two m a piece.
TimingTable small_timing_table() {
    return TimingTable::parse(kTimingHeader +
                                  "xc2v,board_control,-,-,-,4,5.0,1,30,0,flip_flop,flip_flop\n"
                                  "xc2v,compare_lane,float32,-,0,4,12.0,5,16,2,block_ram,flip_flop\n"
                                  "xc2v,compare_lane,float32,-,2,4,9.0,4,16,0,block_ram,flip_flop\n"
                                  "xc2v,compare_lane,fixed16,-,2,4,6.0,2,8,0,block_ram,flip_flop\n"
                                  "xc2v,address_generator,-,1,-,4,4.0,2,10,0,flip_flop,flip_flop\n"
                                  "xc2v,address_generator,-,3,-,4,7.0,3,12,0,flip_flop,flip_flop\n"
                                  "xc2v,tile_walker,-,1,-,4,8.0,5,20,0,flip_flop,flip_flop\n"
                                  "xc2v,tile_walker,-,3,-,4,6.5,5,20,0,flip_flop,flip_flop\n"
                                  "xc2v,pair_collector,block_ram,1,-,4,10.0,6,0,4,block_ram,flip_flop\n"
                                  "xc2v,pair_collector,block_ram,3,-,4,11.0,7,0,6,block_ram,flip_flop\n"
                                  "xc2v,pair_collector,distributed,1,-,4,13.0,8,0,4,lut_ram,flip_flop\n"
                                  "xc2v,pair_collector,distributed,3,-,4,14.0,9,0,6,lut_ram,flip_flop\n"
                                  // Its hits counted a cycle ahead (lanes of latency 2 or more).
                                  "xc2v,pair_collector,block_ram,1,2,4,9.5,6,0,4,block_ram,flip_flop\n"
                                  "xc2v,pair_collector,block_ram,3,2,4,10.5,7,0,6,block_ram,flip_flop\n"
                                  "xc2v,pair_collector,distributed,1,2,4,12.5,8,0,4,lut_ram,flip_flop\n"
                                  "xc2v,pair_collector,distributed,3,2,4,13.5,9,0,6,lut_ram,flip_flop\n",
                              "small.csv");
}

// The small table with the grid board's pieces: fixed8 and fixed24 the synthesised fixed widths.
TimingTable grid_timing_table(double loader_ns) {
    std::string csv = kTimingHeader +
                      "xc2v,board_control,-,-,-,4,5.0,1,30,0,flip_flop,flip_flop\n"
                      "xc2v,compare_lane,float32,-,2,4,9.0,4,16,0,block_ram,flip_flop\n"
                      "xc2v,compare_lane,fixed16,-,2,4,6.0,2,8,0,block_ram,flip_flop\n"
                      "xc2v,address_generator,-,3,-,4,20.0,3,12,0,flip_flop,flip_flop\n"
                      "xc2v,tile_walker,-,3,-,4,21.0,5,20,0,flip_flop,flip_flop\n"
                      "xc2v,pair_collector,block_ram,3,-,4,11.0,7,0,6,block_ram,flip_flop\n"
                      "xc2v,pair_collector,block_ram,3,2,4,10.0,7,0,6,block_ram,flip_flop\n"
                      "xc2v,home_cell_filter,-,3,-,4,4.0,3,0,0,flip_flop,flip_flop\n"
                      "xc2v,grid_cell_function,float32,-,-,4,30.0,6,20,0,flip_flop,flip_flop\n"
                      "xc2v,grid_cell_function,fixed8,-,-,4,25.0,6,10,0,flip_flop,flip_flop\n"
                      "xc2v,grid_cell_function,fixed24,-,-,4,26.0,6,12,0,flip_flop,flip_flop\n"
                      "xc2v,cell_loader,float32,-,-,4," + std::to_string(loader_ns) + ",4,20,0,flip_flop,block_ram\n"
                      "xc2v,cell_loader,fixed8,-,-,4,7.0,4,20,0,flip_flop,block_ram\n"
                      "xc2v,cell_loader,fixed24,-,-,4,7.5,4,20,0,flip_flop,block_ram\n"
                      "xc2v,grid_sequencer,float32,8,-,4,40.0,30,50,4,flip_flop,flip_flop\n";
    return TimingTable::parse(csv, "grid.csv");
}

// A board's pieces alone: no whole-board row (whole_board_timing_test.cpp has them).
BoardTiming pieces_timing(const TimingTable& table, const TimedBoard& board) {
    static const WholeBoardTable none = WholeBoardTable::parse(
        "family,board,format,m,latency,fifo,address_bits,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to\n",
        "none.csv");
    return board_timing(table, none, board);
}

// A piece of the timing by its key; null when it has none.
const PieceTiming* piece_of(const std::vector<PieceTiming>& pieces, const std::string& key) {
    for (const PieceTiming& piece : pieces) {
        if (piece.key == key) return &piece;
    }
    return nullptr;
}

std::string timing_parse_error(const std::string& csv) {
    try {
        TimingTable::parse(csv, "t.csv");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(TimingTable, RefusesAMalformedTableNamingTheLineAndColumn) {
    EXPECT_EQ(timing_parse_error(""), "t.csv: empty; expected the header " + kTimingHeader.substr(0, kTimingHeader.size() - 1));
    EXPECT_EQ(timing_parse_error("family,piece\n").rfind("t.csv:1: expected the header", 0), 0u);
    EXPECT_EQ(timing_parse_error(kTimingHeader + "xc2v,board_control,-\n"), "t.csv:2: expected 12 fields, got 3");
    EXPECT_EQ(timing_parse_error(kTimingHeader + "xc2v,board_control,-,-,-,4,0,1,1,0,flip_flop,flip_flop\n"),
              "t.csv:2: path_ns: expected a positive number of ns, got '0'");
    EXPECT_EQ(timing_parse_error(kTimingHeader + "xc2v,board_control,-,-,-,4,nan,1,1,0,flip_flop,flip_flop\n"),
              "t.csv:2: path_ns: expected a positive number of ns, got 'nan'");
    EXPECT_EQ(timing_parse_error(kTimingHeader + "xc2v,board_control,-,-,-,-,5.0,1,1,0,flip_flop,flip_flop\n"),
              "t.csv:2: speed_grade: expected a grade, got '-'");
    EXPECT_EQ(timing_parse_error(kTimingHeader + "xc2v,board_control,-,-,-,4,5.0,1,1,0,latch,flip_flop\n"),
              "t.csv:2: from: expected flip_flop, block_ram or lut_ram, got 'latch'");
    EXPECT_EQ(timing_parse_error(kTimingHeader + "xc2v,board_control,-,-,-,4,5.0,x,1,0,flip_flop,flip_flop\n"),
              "t.csv:2: luts: expected a whole number or '-', got 'x'");
}

TEST(TimingTable, LooksUpLanesByLatencyAndPiecesByTheSlowerNeighbouringM) {
    const TimingTable table = small_timing_table();
    EXPECT_EQ(table.lane("xc2v", 4, "float32", 0).ns, 12.0);
    EXPECT_EQ(table.lane("xc2v", 4, "float32", 2).ns, 9.0);
    // Latency 1 was not synthesised: the shallower row, never a faster guess.
    EXPECT_EQ(table.lane("xc2v", 4, "float32", 1).ns, 12.0);
    // Past the deepest row the extra stages only delay the AND.
    EXPECT_EQ(table.lane("xc2v", 4, "float32", 7).ns, 9.0);
    EXPECT_EQ(table.address_generator("xc2v", 4, 2).ns, 7.0);  // the slower of m = 1 and m = 3
    EXPECT_EQ(table.tile_walker("xc2v", 4, 2).ns, 8.0);        // the slower even when it is the smaller m
    EXPECT_EQ(table.pair_collector("xc2v", 4, 1, "distributed", false).from, "lut_ram");
    // The FIFO's rows by how it counts its hits: in their cycle, or a cycle ahead.
    EXPECT_EQ(table.pair_collector("xc2v", 4, 2, "block_ram", false).ns, 11.0);
    EXPECT_EQ(table.pair_collector("xc2v", 4, 2, "block_ram", true).ns, 10.5);
    EXPECT_EQ(table.control("xc2v", 4).carry_cells, 30u);
    EXPECT_DOUBLE_EQ(table.control("xc2v", 4).fmax_mhz(), 200.0);
}

TEST(TimingTable, NamesWhatIsMissing) {
    const TimingTable table = small_timing_table();
    const auto message = [](auto&& lookup) {
        try {
            lookup();
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message([&] { table.lane("xc2v", 5, "float32", 2); }),
              "no timing of the float32 comparison lane for the xc2v family at speed grade -5");
    EXPECT_EQ(message([&] { table.lane("xc2v", 4, "fixed16", 0); }),
              "no timing of the fixed16 comparison lane at compare latency 0 for the xc2v family");
    EXPECT_EQ(message([&] { table.address_generator("xc2v", 4, 4); }),
              "no timing of the address generator around m = 4 for the xc2v family");
    EXPECT_EQ(message([&] { table.control("xcup", 1); }),
              "no timing of the controller for the xcup family at speed grade -1");
    EXPECT_EQ(table.speed_grades("xc2v"), std::vector<uint32_t>{4});
    EXPECT_TRUE(table.speed_grades("xcup").empty());
}

TEST(BoardTiming, TheSlowestPieceSetsTheFmax) {
    const TimingTable table = small_timing_table();
    TimedBoard board{"xc2v", 4, "float32", 3, 2, FifoMemory::kBlockRam, false};
    BoardTiming timing = pieces_timing(table, board);
    ASSERT_EQ(timing.pieces.size(), 4u);
    // The pair FIFO (10.5 ns, its hits counted a cycle ahead at compare
    // latency 2) limits, above the lane (9 ns): every piece holds the clock.
    EXPECT_TRUE(timing.awaiting_pipelining.empty());
    EXPECT_NE(timing.whole_board_missing, "") << "no whole-board row: the pieces alone";
    EXPECT_EQ(timing.limiting().piece, "pair FIFO in block RAM");
    EXPECT_DOUBLE_EQ(timing.fmax_mhz(), 1e3 / 10.5);
    EXPECT_EQ(&timing.slowest(), &timing.limiting());
    board.fifo_memory = FifoMemory::kDistributed;
    EXPECT_EQ(pieces_timing(table, board).limiting().piece, "pair FIFO in LUTs");
    EXPECT_DOUBLE_EQ(pieces_timing(table, board).limiting().path.ns, 13.5);
    // At compare latency 0 the lane takes 12 ns, and the FIFO counts the
    // hits in their cycle (14 ns).
    board.compare_latency = 0;
    EXPECT_DOUBLE_EQ(pieces_timing(table, board).limiting().path.ns, 14.0);
    board.fifo_memory = FifoMemory::kBlockRam;
    EXPECT_DOUBLE_EQ(pieces_timing(table, board).limiting().path.ns, 12.0);  // the lane, above the FIFO's 11
    board.compare_latency = 2;
    // Boxes in SSRAM tiles: the tile walker instead of the address generator,
    // held to the clock like it.
    board.tiled = true;
    timing = pieces_timing(table, board);
    EXPECT_EQ(timing.pieces[1].piece, "tile walker");
    EXPECT_DOUBLE_EQ(timing.pieces[1].path.ns, 6.5);
    // Where the walker is the slowest (21 ns against the FIFO's 10), it sets
    // the Fmax; untiled, the address generator (20 ns) does.
    timing = pieces_timing(grid_timing_table(6.0), board);
    EXPECT_EQ(timing.limiting().piece, "tile walker");
    EXPECT_DOUBLE_EQ(timing.fmax_mhz(), 1e3 / 21.0);
    board.tiled = false;
    EXPECT_EQ(pieces_timing(grid_timing_table(6.0), board).limiting().piece, "address generator");
}

TEST(BoardTiming, AGridBoardIsHeldToItsCellLoaderNotToTheSeedsAddressPieces) {
    TimedBoard board{"xc2v", 4, "float32", 3, 2, FifoMemory::kBlockRam, false, true};
    BoardTiming timing = pieces_timing(grid_timing_table(6.0), board);
    const auto keys = [](const std::vector<PieceTiming>& pieces) {
        std::vector<std::string> names;
        for (const PieceTiming& piece : pieces) names.push_back(piece.key);
        return names;
    };
    // The cell-function unit, binning sequencer and one-cell filter are held
    // to the clock once they are pipelined; reported beside it until then.
    // So is the pair FIFO behind the unregistered one-cell filter.
    const std::vector<std::string> pipelined{"cell_function", "sequencer", "one_cell_filter", "pair_fifo"};
    if (kGridPiecesAwaitPipelining) {
        EXPECT_EQ(keys(timing.pieces), (std::vector<std::string>{"lane", "cell_loader", "controller"}));
        EXPECT_EQ(keys(timing.awaiting_pipelining), pipelined);
        // The lane (9 ns) limits; the sequencer as written (40 ns) is the slowest of all.
        EXPECT_EQ(timing.limiting().piece, "float32 comparison lane at compare latency 2");
        EXPECT_EQ(timing.slowest().piece, "binning sequencer");
    } else {
        EXPECT_EQ(keys(timing.pieces), (std::vector<std::string>{"lane", "cell_function", "cell_loader", "sequencer",
                                                                 "one_cell_filter", "pair_fifo", "controller"}));
        EXPECT_TRUE(timing.awaiting_pipelining.empty());
        EXPECT_EQ(&timing.slowest(), &timing.limiting());
    }
    const PieceTiming* unit = piece_of(kGridPiecesAwaitPipelining ? timing.awaiting_pipelining : timing.pieces,
                                       "cell_function");
    ASSERT_NE(unit, nullptr);
    EXPECT_EQ(unit->piece, "float32 cell-function unit");
    EXPECT_DOUBLE_EQ(unit->path.ns, 30.0);
    // A slower loader (12 ns) limits the grid board; the address generator (20 ns) and tile
    // walker (21 ns), which it has not, would have limited it before it.
    timing = pieces_timing(grid_timing_table(12.0), board);
    if (kGridPiecesAwaitPipelining) {
        EXPECT_EQ(timing.limiting().piece, "float32 cell loader");
        EXPECT_DOUBLE_EQ(timing.fmax_mhz(), 1e3 / 12.0);
    }
    // The fixed16 loader: fixed16 lies between the synthesised fixed8 (7 ns)
    // and fixed24 (7.5 ns) and takes the slower; so does its cell-function unit.
    board.format = "fixed16";
    timing = pieces_timing(grid_timing_table(6.0), board);
    ASSERT_NE(piece_of(timing.pieces, "cell_loader"), nullptr);
    EXPECT_EQ(piece_of(timing.pieces, "cell_loader")->piece, "fixed16 cell loader");
    EXPECT_DOUBLE_EQ(piece_of(timing.pieces, "cell_loader")->path.ns, 7.5);
    EXPECT_DOUBLE_EQ(timing.slowest().path.ns, kGridPiecesAwaitPipelining ? 40.0 : timing.limiting().path.ns);
    // The grid board's one-cell filter stands between its lanes and the FIFO,
    // which counts its cycle's hits (11 ns); the seed's board's FIFO has them
    // counted a cycle ahead by lanes of latency 2 (10 ns).
    const auto fifo_ns = [](const BoardTiming& t) {
        const PieceTiming* fifo = piece_of(t.pieces, "pair_fifo");
        if (fifo == nullptr) fifo = piece_of(t.awaiting_pipelining, "pair_fifo");
        return fifo == nullptr ? 0.0 : fifo->path.ns;
    };
    EXPECT_DOUBLE_EQ(fifo_ns(timing), 11.0);
    // The seed's board on the same table: its address generator, none of the grid's pieces.
    board.grid = false;
    timing = pieces_timing(grid_timing_table(12.0), board);
    EXPECT_DOUBLE_EQ(fifo_ns(timing), 10.0);
    EXPECT_EQ(timing.limiting().piece, "address generator");
    for (const PieceTiming& piece : timing.pieces) {
        EXPECT_EQ(piece.key.find("cell"), std::string::npos) << piece.key;
        EXPECT_NE(piece.key, "sequencer");
    }
    // A fixed width outside the synthesised ones is named as missing.
    try {
        grid_timing_table(6.0).cell_function("xc2v", 4, "fixed32");
        ADD_FAILURE() << "fixed32 found";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "no timing of the fixed32 cell-function unit for the xc2v family at speed grade -4 "
                               "(no synthesised width on both sides)");
    }
}

// What the stored table (the RTL, synthesised and timed) says, for every
// family and speed grade in it.
class StoredTiming : public ::testing::Test {
protected:
    const TimingTable& table = TimingTable::stored();
    static std::vector<std::string> fixed_formats() {
        std::vector<std::string> formats;
        for (int k = 8; k <= 32; ++k) formats.push_back("fixed" + std::to_string(k));
        return formats;
    }
    template <class Check>
    void for_each_grade(Check check) const {
        for (const std::string family : {"xc2v", "xcup"}) {
            const std::vector<uint32_t> grades = table.speed_grades(family);
            ASSERT_EQ(grades.size(), 3u) << family;
            for (const uint32_t grade : grades) check(family, grade);
        }
    }
};

TEST_F(StoredTiming, MoreCompareStagesMakeAFasterLane) {
    for_each_grade([&](const std::string& family, uint32_t grade) {
        std::vector<std::string> formats = fixed_formats();
        formats.push_back("float32");
        for (const std::string& format : formats) {
            const double l0 = table.lane(family, grade, format, 0).ns;
            const double l1 = table.lane(family, grade, format, 1).ns;
            const double l2 = table.lane(family, grade, format, 2).ns;
            // The first stage takes the AND of the six comparators off the path.
            EXPECT_GT(l0, l1) << family << " -" << grade << " " << format;
            EXPECT_GE(l1, l2) << family << " -" << grade << " " << format;
            EXPECT_EQ(table.lane(family, grade, format, 9).ns, l2) << "stages past the second only delay the AND";
        }
    });
}

TEST_F(StoredTiming, FixedPointLanesAreFasterThanFloat32AndWiderOnesNoFaster) {
    for_each_grade([&](const std::string& family, uint32_t grade) {
        for (uint32_t latency = 0; latency <= 2; ++latency) {
            const double float32 = table.lane(family, grade, "float32", latency).ns;
            double narrower = 0;
            for (const std::string& format : fixed_formats()) {
                const double ns = table.lane(family, grade, format, latency).ns;
                EXPECT_LT(ns, float32) << family << " -" << grade << " " << format << " at latency " << latency;
                // A wider comparator is a longer carry chain.
                EXPECT_GE(ns, narrower) << family << " -" << grade << " " << format << " at latency " << latency;
                narrower = ns;
            }
            EXPECT_GT(table.lane(family, grade, "fixed32", latency).carry_cells,
                      table.lane(family, grade, "fixed8", latency).carry_cells);
        }
    });
}

// The FIFO counts 2m-1 hits in a tree of adds and finds the lowest on a
// carry chain: its path grows with the lanes, about as their logarithm;
// synthesis's choices scatter it a few percent from one m to the next (up to
// 7% on the VU9P), never more than 10%. From 1 lane to 63 it grows by a third
// at least (1.48 times on the VU9P, where the memory's clock-to-out, the same
// at every m, is much of the path).
TEST_F(StoredTiming, TheFifoGrowsDeeperAndSlowerWithTheLanes) {
    for_each_grade([&](const std::string& family, uint32_t grade) {
        for (const std::string memory : {"block_ram", "distributed"}) {
            for (const bool ahead : {false, true}) {
                const std::string what = family + " -" + std::to_string(grade) + " " + memory +
                                         (ahead ? ", counted ahead" : "");
                double fewer = 0;  // the slowest with fewer lanes
                for (const uint32_t m : {1u, 2u, 3u, 4u, 6u, 8u, 12u, 16u, 24u, 32u}) {
                    const PathDelay path = table.pair_collector(family, grade, m, memory, ahead);
                    EXPECT_GE(path.ns, 0.9 * fewer) << what << " m = " << m;
                    fewer = std::max(fewer, path.ns);
                }
                const PathDelay one = table.pair_collector(family, grade, 1, memory, ahead);
                const PathDelay many = table.pair_collector(family, grade, BoardConfig::kMaxM, memory, ahead);
                EXPECT_GT(many.ns, 1.33 * one.ns) << what;
                EXPECT_GT(many.luts + many.carry_cells + many.wide_muxes, one.luts + one.carry_cells + one.wide_muxes)
                    << what;
            }
        }
    });
}

TEST_F(StoredTiming, AFasterSpeedGradeIsFasterEverywhere) {
    for (const std::string family : {"xc2v", "xcup"}) {
        const std::vector<uint32_t> grades = table.speed_grades(family);
        for (std::size_t g = 1; g < grades.size(); ++g) {
            const uint32_t slow = grades[g - 1], fast = grades[g];
            EXPECT_LT(table.control(family, fast).ns, table.control(family, slow).ns);
            EXPECT_LT(table.lane(family, fast, "float32", 2).ns, table.lane(family, slow, "float32", 2).ns);
            for (const uint32_t m : {1u, 8u, 32u}) {
                EXPECT_LT(table.address_generator(family, fast, m).ns, table.address_generator(family, slow, m).ns);
                EXPECT_LT(table.tile_walker(family, fast, m).ns, table.tile_walker(family, slow, m).ns);
                for (const bool ahead : {false, true}) {
                    EXPECT_LT(table.pair_collector(family, fast, m, "block_ram", ahead).ns,
                              table.pair_collector(family, slow, m, "block_ram", ahead).ns);
                }
            }
        }
    }
}

}  // namespace
}  // namespace cdvp
