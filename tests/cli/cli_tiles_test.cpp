// Scenes past the block RAMs: boxes in SSRAM swept in tiles, from the command
// line (board.memory, board.tile_boxes), the report naming the memory that
// served, and the refusals past the SSRAM or the block RAMs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliTiles : public Cli {
protected:
    std::string spheres(uint32_t objects, uint32_t frames = 2) const {
        return "run --scene spheres --objects " + std::to_string(objects) + " --frames " + std::to_string(frames) +
               " --quiet --board adm-xrc-ii ";
    }
    json report() const { return report_of(dir_ / "r.json"); }
};

// Every frame's cycle count is the schedule's slots + L + stalls, and the
// pairs are the block-RAM board's (as a set: the order is the schedule's).
void expect_cycle_identity(const json& r) {
    const uint64_t latency = r["config"]["pipeline_latency_cycles"];
    for (const json& f : r["frames"]) {
        EXPECT_EQ(f["compute_cycles"].get<uint64_t>(),
                  f["sweep_cycles"].get<uint64_t>() + latency + f["stall_cycles"].get<uint64_t>());
    }
}

TEST_F(CliTiles, SsramWithExplicitTilesOnBothEnginesFindsTheBlockRamBoardsPairs) {
    ASSERT_EQ(run(spheres(300) + "--m 4 -c board.memory=block_ram --pairs-out bram.csv --report r.json").status, 0);
    const json in_block_ram = report();
    EXPECT_EQ(in_block_ram["config"]["memory"], "block RAM");
    EXPECT_EQ(in_block_ram["config"]["tile_boxes"], 0);
    for (const char* fidelity : {"fast", "cycle"}) {
        const std::string pairs = std::string(fidelity) + ".csv";
        const Result r = run(spheres(300) + "--m 4 -c board.memory=ssram -c board.tile_boxes=64 --fidelity " +
                             fidelity + " --pairs-out " + pairs + " --report r.json");
        ASSERT_EQ(r.status, 0) << r.err;
        const json tiled = report();
        EXPECT_EQ(tiled["config"]["memory"], "SSRAM");
        EXPECT_EQ(tiled["config"]["tile_boxes"], 64);
        EXPECT_EQ(tiled["config"]["tiles"], 5);  // ceil(300 / 64)
        EXPECT_EQ(tiled["config"]["block_rams"], 60);  // 6 x (2m+2) x ceil(64/512)
        EXPECT_GT(tiled["config"]["load_wait_slots"].get<uint64_t>(), 65u);  // at least the first load
        EXPECT_EQ(tiled["frames"][0]["load_wait_slots"], tiled["config"]["load_wait_slots"]);
        expect_cycle_identity(tiled);
        for (std::size_t k = 0; k < 2; ++k) {
            EXPECT_EQ(tiled["frames"][k]["pairs"], in_block_ram["frames"][k]["pairs"]);
            EXPECT_GT(tiled["frames"][k]["sweep_cycles"].get<uint64_t>(),
                      in_block_ram["frames"][k]["sweep_cycles"].get<uint64_t>());
        }
    }
    EXPECT_EQ(slurp(dir_ / "fast.csv"), slurp(dir_ / "cycle.csv")) << "both engines, the same pairs";
}

// auto: block RAM while the boxes fit (the paper's 500 at m = 24), SSRAM past it
// with the largest tile whose buffers fit: 6 x 18 x 1 = 108 of 144 block RAMs at m = 8.
TEST_F(CliTiles, AutoKeepsBlockRamWhileItFitsAndTilesPastIt) {
    ASSERT_EQ(run(spheres(500, 1) + "--m 24 --report r.json").status, 0);
    EXPECT_EQ(report()["config"]["memory"], "block RAM");
    const Result r = run(spheres(2000, 1) + "--m 8 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json tiled = report();
    EXPECT_EQ(tiled["config"]["memory"], "SSRAM");
    EXPECT_EQ(tiled["config"]["tile_boxes"], 512);
    EXPECT_EQ(tiled["config"]["tiles"], 4);
    EXPECT_EQ(tiled["config"]["resources"]["block_rams"]["used"].get<double>(),
              108 + tiled["config"]["resources"]["pieces"]["pair_collector"]["block_rams"].get<double>());
    EXPECT_TRUE(tiled["config"]["resources"]["fits"].get<bool>());
    expect_cycle_identity(tiled);
}

// The clocked board's waveforms show the loader: the tiles of the block, a
// load under way and the bubbles waiting for one.
TEST_F(CliTiles, WaveformsShowTheTileLoader) {
    ASSERT_EQ(run("run --scene spheres --objects 40 --frames 1 --quiet --m 2 -c board.memory=ssram "
                  "-c board.tile_boxes=16 --vcd w.vcd").status, 0);
    const std::string vcd = slurp(dir_ / "w.vcd");
    for (const char* signal : {"row_tile", "column_tile", "loading", "wait"}) {
        const std::size_t at = vcd.find(std::string(" ") + signal + " ");
        ASSERT_NE(at, std::string::npos) << signal;
        const std::size_t line = vcd.rfind("$var", at);
        std::istringstream words(vcd.substr(line, at - line));
        std::string var, kind, width, id;
        words >> var >> kind >> width >> id;
        const std::string high = width == "1" ? "\n1" + id + "\n" : "\nb10 " + id + "\n";  // 1, or tile 2
        EXPECT_NE(vcd.find(high), std::string::npos) << signal << " never reaches " << high;
    }
}

TEST_F(CliTiles, SixtyFiveThousandBoxesRunOnThePapersBoard) {
    const Result r = run(spheres(65536, 1) + "--m 8 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json big = report();
    EXPECT_EQ(big["config"]["memory"], "SSRAM");
    EXPECT_EQ(big["config"]["tiles"], 128);
    EXPECT_GT(big["frames"][0]["pairs"].get<uint64_t>(), 10000u);
    expect_cycle_identity(big);
}

// fixed16 puts min and max of an axis in one 36-bit word: tile buffers of
// 3 x (2m+2) primitives, so the XC2V6000 holds m = 23 instead of 11.
TEST_F(CliTiles, PackedFixedPointWordsFitTwiceTheLanesInSsramTiles) {
    const Result r = run(spheres(65536, 1) + "--m 23 --format fixed16 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json packed = report();
    EXPECT_EQ(packed["config"]["memory"], "SSRAM");
    EXPECT_EQ(packed["config"]["resources"]["block_rams"]["used"], 144);
    EXPECT_EQ(packed["config"]["resources"]["largest_m"], 23);
    expect_cycle_identity(packed);
    const Result wider = run(spheres(65536, 1) + "--m 24 --format fixed16");
    EXPECT_EQ(wider.status, 2);
    EXPECT_NE(wider.err.find("(largest m that fits: 23;"), std::string::npos) << wider.err;
}

TEST_F(CliTiles, ScenesPastTheSsramAreRefused) {
    expect_refusal(run(spheres(2000, 1) + "--m 8 -c device.ssram_words=1000 --report r.json"),
                   "cdvp run: -c device.ssram_words: 1000 words a bank in 6 SSRAM banks hold 1000 boxes, too few "
                   "for 2000 objects (--objects)");
    // Three banks take turns: two cycles a box, half the boxes.
    expect_refusal(run(spheres(2000, 1) + "--m 8 -c device.ssram_banks=3 -c device.ssram_words=3000"),
                   "cdvp run: -c device.ssram_words: 3000 words a bank in 3 SSRAM banks hold 1500 boxes");
    // Past the ADM-XRC-II's 524,288 boxes (at 512 a tile, also past the tiles the schedule allows):
    // the SSRAM is named.
    expect_refusal(run(spheres(524289, 1) + "--m 11"),
                   "cdvp run: " + preset("adm-xrc-ii") +
                       ": device.ssram_words: 524288 words a bank in 6 SSRAM banks hold 524288 boxes, too few for "
                       "524289 objects (--objects) (memory=auto (the default of --memory)): use fewer objects");
    expect_refusal(run(spheres(100, 1) + "-c board.memory=ssram -c device.ssram_banks=0"),
                   "cdvp run: -c device.ssram_banks: the device has no off-chip SSRAM");
    EXPECT_EQ(files(), std::vector<std::string>{}) << "a refused run leaves no output";
}

TEST_F(CliTiles, TileBuffersPastTheBlockRamsAndTooManyTilesAreRefused) {
    // m = 24: 6 x 50 block RAMs for even the smallest tile; m = 11 is the most (6 x 24 = 144).
    expect_refusal(run(spheres(500, 1) + "--m 24 -c board.memory=ssram"),
                   "cdvp run: " + preset("adm-xrc-ii") +
                       ": device.block_rams: 144 block RAMs are too few for the SSRAM tile buffers of --m 24");
    const Result r = run(spheres(500, 1) + "--m 24 -c board.memory=ssram");
    EXPECT_NE(r.err.find("(largest m that fits: 11; --ignore-capacity runs it anyway)"), std::string::npos) << r.err;
    EXPECT_EQ(run(spheres(500, 1) + "--m 11 -c board.memory=ssram").status, 0);
    expect_refusal(run(spheres(2000, 1) + "--m 1 -c board.memory=ssram -c board.tile_boxes=1"),
                   "cdvp run: -c board.tile_boxes: tiles of 1 boxes make 2000 tiles of 2000 objects (--objects); "
                   "expected at most 1024 tiles");
}

// The refusal's formula is the number format's own layout: word groups a
// box, boxes a primitive; its product is the count it names.
TEST_F(CliTiles, ATileRefusalGivesTheFormatsOwnBlockRamFormula) {
    const std::string at = "--m 24 -c board.memory=ssram";
    EXPECT_NE(run(spheres(500, 1) + at).err.find("they need 6 x (2m+2) x ceil(T/512) = 300 (largest m that fits: 11;"),
              std::string::npos);
    EXPECT_NE(run(spheres(500, 1) + at + " --format fixed16")
                  .err.find("they need 3 x (2m+2) x ceil(T/512) = 150 (largest m that fits: 23;"),
              std::string::npos);
    // 3 x 66 x ceil(60000/1024) = 11682
    EXPECT_NE(run(spheres(60000, 1) + "--m 32 --memory ssram --tile-boxes 60000 --format fixed8")
                  .err.find("they need 3 x (2m+2) x ceil(T/1024) = 11682 (not even m=1 fits"),
              std::string::npos);
}

TEST_F(CliTiles, TheLargestMOfARefusalCountsTheSsramTilesThatAutoWouldUse) {
    // 1,600 boxes: in block RAM m <= 6 (6 x m x 4 <= 144), in SSRAM tiles m <= 11.
    const Result refused = run(spheres(1600, 1) + "--m 16");
    EXPECT_EQ(refused.status, 2);
    EXPECT_NE(refused.err.find("(largest m that fits: 11; --ignore-capacity runs it anyway)"), std::string::npos)
        << refused.err;
    EXPECT_EQ(run(spheres(1600, 1) + "--m 11").status, 0);
    EXPECT_EQ(run(spheres(1600, 1) + "--m 12").status, 2);
    // Asked to stay in block RAM, it names the block RAM's largest m.
    const Result in_block_ram = run(spheres(1600, 1) + "--m 16 --memory block_ram");
    EXPECT_NE(in_block_ram.err.find("(largest m that fits: 6; --ignore-capacity"), std::string::npos) << in_block_ram.err;
    EXPECT_EQ(run(spheres(1600, 1) + "--m 6 --memory block_ram").status, 0);
}

}  // namespace
}  // namespace cdvp::test
