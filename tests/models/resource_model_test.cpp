#include "models/resources/resource_model.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "models/board_spec/board_config.h"

namespace cdvp {
namespace {

const std::string kHeader =
    "family,piece,format,m,address_bits,fifo_depth,luts,lutram_luts,flip_flops,carry_cells,block_rams_18k,"
    "multipliers\n";

// A small table: the controller, two lanes, and two m per piece.
SynthesisTable small_table() {
    return SynthesisTable::parse(kHeader +
                                     "xc2v,board_control,-,-,-,-,10,0,20,5,0,0\n"
                                     "xc2v,compare_lane,float32,-,-,-,400,0,8,100,0,0\n"
                                     "xc2v,compare_lane,fixed8,-,-,-,50,0,8,20,0,0\n"
                                     "xc2v,address_generator,-,1,16,-,100,0,50,30,0,0\n"
                                     "xc2v,address_generator,-,3,16,-,300,0,50,90,0,0\n"
                                     "xc2v,pair_collector,block_ram,1,16,512,60,40,30,40,1,0\n"
                                     "xc2v,pair_collector,block_ram,3,16,512,1000,200,100,200,1,0\n"
                                     "xc2v,pair_collector,distributed,1,16,512,200,2000,30,40,0,0\n"
                                     "xc2v,pair_collector,distributed,3,16,512,1400,2200,100,200,0,0\n"
                                     "xc2v,grid_cell_function,float32,-,-,-,900,0,140,250,0,4\n"
                                     "xc2v,grid_cell_function,fixed8,-,-,-,700,0,130,300,0,4\n"
                                     "xc2v,grid_cell_function,fixed16,-,-,-,800,0,130,300,0,4\n"
                                     "xc2v,home_cell_filter,-,1,-,-,7,0,0,0,0,0\n"
                                     "xc2v,home_cell_filter,-,3,-,-,27,0,0,0,0,0\n"
                                     "xc2v,grid_sequencer,float32,8,16,-,5000,0,600,2000,0,6\n",
                                 "small.csv");
}

std::string parse_error(const std::string& csv) {
    try {
        SynthesisTable::parse(csv, "t.csv");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(SynthesisTable, RefusesAMalformedTableNamingTheLine) {
    EXPECT_EQ(parse_error(""), "t.csv: empty; expected the header " + kHeader.substr(0, kHeader.size() - 1));
    EXPECT_EQ(parse_error("family,piece\n").rfind("t.csv:1: expected the header", 0), 0u);
    EXPECT_EQ(parse_error(kHeader + "xc2v,compare_lane,float32\n"), "t.csv:2: expected 12 fields, got 3");
    EXPECT_EQ(parse_error(kHeader + "xc2v,board_control,-,-,-,-,1O,0,2,0,0,0\n"),
              "t.csv:2: luts: expected a whole number or '-', got '1O'");
    EXPECT_EQ(parse_error(kHeader + "xc2v,board_control,-,-,-,-,-5,0,2,0,0,0\n"),
              "t.csv:2: luts: expected a whole number or '-', got '-5'");
}

TEST(SynthesisTable, CountsDistributedRamAsLutsAndInterpolatesInM) {
    const SynthesisTable table = small_table();
    EXPECT_EQ(table.pair_collector("xc2v", 1, "block_ram").luts, 100);  // 60 logic + 40 as RAM
    EXPECT_EQ(table.pair_collector("xc2v", 1, "block_ram").block_rams, 1);
    EXPECT_EQ(table.pair_collector("xc2v", 1, "distributed").luts, 2200);
    const Resources m2 = table.address_generator("xc2v", 2);  // halfway between m = 1 and m = 3
    EXPECT_DOUBLE_EQ(m2.luts, 200);
    EXPECT_DOUBLE_EQ(m2.carry_cells, 60);
    EXPECT_DOUBLE_EQ(table.pair_collector("xc2v", 2, "block_ram").luts, 650);
    EXPECT_THROW(table.address_generator("xc2v", 4), std::invalid_argument);  // beyond the rows: no guess
    EXPECT_THROW(table.lane("xcup", "float32"), std::invalid_argument);
    EXPECT_THROW(table.lane("xc2v", "fixed12"), std::invalid_argument);
}

const DeviceCapacity kDevice{"D", "xc2v", 100000, 100000, 14, "test"};

TEST(BoardResources, AreLanesTimesALanePlusEveryPiece) {
    const SynthesisTable table = small_table();
    const BoardResources r = board_resources(table, kDevice, "float32", 2, 12);
    EXPECT_DOUBLE_EQ(r.lanes.luts, 3 * 400);
    EXPECT_DOUBLE_EQ(r.coordinate_memories.block_rams, 12);
    EXPECT_EQ(r.pair_fifo_memory, FifoMemory::kBlockRam);
    EXPECT_STREQ(fifo_memory_name(r.pair_fifo_memory), "block_ram");
    const Resources total = r.total();
    EXPECT_DOUBLE_EQ(total.luts, 1200 + 200 + 650 + 10);
    EXPECT_DOUBLE_EQ(total.flip_flops, 24 + 50 + 65 + 20);
    EXPECT_DOUBLE_EQ(total.block_rams, 12 + 1);
    const BoardResources narrow = board_resources(table, kDevice, "fixed8", 2, 12);
    EXPECT_DOUBLE_EQ(narrow.lanes.luts, 3 * 50);
}

TEST(BoardResources, PutThePairFifoInLutsWhenTheMemoriesTakeEveryBlockRam) {
    const SynthesisTable table = small_table();
    const BoardResources r = board_resources(table, kDevice, "float32", 2, 14);
    EXPECT_EQ(r.pair_fifo_memory, FifoMemory::kDistributed);
    EXPECT_STREQ(fifo_memory_name(r.pair_fifo_memory), "distributed");
    EXPECT_DOUBLE_EQ(r.total().block_rams, 14);
    EXPECT_DOUBLE_EQ(r.pair_collector.luts, (2200 + 3600) / 2);
}

TEST(BoardResources, TheGridBoardAddsSixCellFunctionsItsFilterAndItsSequencerAroundItsCellBuffer) {
    const SynthesisTable table = small_table();
    const BoardResources all_pairs = board_resources(table, kDevice, "float32", 2, 12);
    const BoardResources grid = grid_board_resources(table, kDevice, "float32", 2, 12);
    EXPECT_STREQ(all_pairs.memories_hold, "the boxes");
    EXPECT_STREQ(grid.memories_hold, "the cell buffer");
    EXPECT_DOUBLE_EQ(all_pairs.grid_blocks.luts, 0);
    // The filter at m = 2: between m = 1 and 3; the sequencer's one row whatever m and the format.
    EXPECT_DOUBLE_EQ(grid.grid_blocks.luts, 6 * 900 + (7 + 27) / 2.0 + 5000);
    EXPECT_DOUBLE_EQ(grid.grid_blocks.multipliers, 6 * 4 + 6);
    EXPECT_DOUBLE_EQ(grid_board_resources(table, kDevice, "fixed8", 3, 12).grid_blocks.flip_flops, 6 * 130 + 600);
    EXPECT_DOUBLE_EQ(grid.total().luts, all_pairs.total().luts + grid.grid_blocks.luts);
    EXPECT_DOUBLE_EQ(grid.total().block_rams, all_pairs.total().block_rams);
    // fixedK between two synthesised widths: interpolated in K; beyond them, no guess.
    EXPECT_DOUBLE_EQ(table.cell_function("xc2v", "fixed12").luts, 750);
    EXPECT_DOUBLE_EQ(table.cell_function("xc2v", "fixed16").luts, 800);
    EXPECT_THROW(grid_board_resources(table, kDevice, "fixed20", 2, 12), std::invalid_argument);
    EXPECT_THROW(table.cell_function("xcup", "float32"), std::invalid_argument);
}

TEST(Utilisation, NamesTheFirstResourceThatOverflows) {
    const DeviceCapacity device{"D", "xc2v", 1000, 1000, 10, "test"};
    EXPECT_TRUE(utilisation({900, 900, 0, 10, 0}, device).fits());
    EXPECT_DOUBLE_EQ(utilisation({900, 500, 0, 5, 0}, device).flip_flops, 0.5);
    EXPECT_EQ(utilisation({1001, 900, 0, 10, 0}, device).overflow, "LUTs");
    EXPECT_EQ(utilisation({900, 1200, 0, 10, 0}, device).overflow, "flip-flops");
    EXPECT_EQ(utilisation({900, 900, 0, 11, 0}, device).overflow, "block RAMs");
}

// The table compiled into cdvp: every format the CLI offers, on both families (xc2v, xcup),
// and the costs ordered as the hardware orders them.
TEST(StoredSynthesisTable, CoversEveryFormatAndMOnBothFamilies) {
    const SynthesisTable& table = SynthesisTable::stored();
    for (const char* family : {"xc2v", "xcup"}) {
        const Resources float_lane = table.lane(family, "float32");
        double previous = 0;
        for (int k = 8; k <= 32; ++k) {
            const Resources lane = table.lane(family, "fixed" + std::to_string(k));
            EXPECT_LT(lane.luts, float_lane.luts) << family << " fixed" << k;
            if (k % 8 == 0) {  // wider words cost more (checked at whole bytes: synthesis is not monotone bit by bit)
                EXPECT_GT(lane.luts, previous) << family << " fixed" << k;
                previous = lane.luts;
            }
        }
        for (uint32_t m = 1; m <= BoardConfig::kMaxM; ++m) {
            EXPECT_GT(table.address_generator(family, m).luts, 0) << family << " m = " << m;
            for (const char* memory : {"block_ram", "distributed"}) {
                EXPECT_GT(table.pair_collector(family, m, memory).luts, 0) << family << " m = " << m << memory;
            }
        }
        EXPECT_GT(table.address_generator(family, 24).luts, table.address_generator(family, 1).luts);
        EXPECT_GT(table.control(family).flip_flops, 0);
        // The grid board's pieces in every format and at every m.
        const Resources float_unit = table.cell_function(family, "float32");
        EXPECT_GT(float_unit.luts, 0) << family;
        for (int k = 8; k <= 32; ++k) {
            EXPECT_GT(table.cell_function(family, "fixed" + std::to_string(k)).luts, 0) << family << " fixed" << k;
        }
        for (uint32_t m = 1; m <= BoardConfig::kMaxM; ++m) {
            EXPECT_GT(table.home_cell_filter(family, m).luts, 0) << family << " m = " << m;
        }
        EXPECT_GT(table.home_cell_filter(family, 24).luts, table.home_cell_filter(family, 1).luts) << family;
    }
}

}  // namespace
}  // namespace cdvp
