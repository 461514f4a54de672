// The grid board from the command line (board.algorithm grid,
// docs/grid_board.md): the all-pairs board's pairs at every level and in
// fixed point, the report's cycles, its waveforms, and the refusals past its
// cell buffer or its SSRAM.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliGrid : public Cli {
protected:
    std::string spheres(uint32_t objects, uint32_t frames = 2) const {
        return "run --scene spheres --objects " + std::to_string(objects) + " --frames " + std::to_string(frames) +
               " --quiet --board adm-xrc-ii ";
    }
    json report(const std::string& name = "r.json") const { return report_of(dir_ / name); }
};

// The same pairs as the all-pairs board (the CSV is sorted by id), at the
// fast, cycle and analytic levels; each frame's cycles are its slots + L +
// stalls, far fewer than the all-pairs board's.
TEST_F(CliGrid, FindsTheAllPairsBoardsPairsAtEveryLevel) {
    ASSERT_EQ(run(spheres(3000) + "--pairs-out all.csv --report all.json").status, 0);
    for (const char* level : {"fast", "cycle", "analytic"}) {
        const std::string name = std::string(level);
        const Result r = run(spheres(3000) + "-c board.algorithm=grid --fidelity " + name + " --pairs-out " + name +
                             ".csv --report " + name + ".json");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(slurp(dir_ / (name + ".csv")), slurp(dir_ / "all.csv")) << level;
        const json grid = report(name + ".json");
        EXPECT_EQ(grid["config"]["settings"]["board.algorithm"]["value"], "grid");
        const uint64_t latency = grid["config"]["pipeline_latency_cycles"];
        for (std::size_t k = 0; k < 2; ++k) {
            const json& f = grid["frames"][k];
            EXPECT_EQ(f["compute_cycles"].get<uint64_t>(),
                      f["sweep_cycles"].get<uint64_t>() + latency + f["stall_cycles"].get<uint64_t>())
                << level;
            EXPECT_LT(10 * f["compute_cycles"].get<uint64_t>(),
                      report("all.json")["frames"][k]["compute_cycles"].get<uint64_t>())
                << level << ": 3,000 boxes in a grid take a tenth of all pairs' cycles at most";
        }
    }
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(report("fast.json")["frames"][k]["compute_cycles"], report("cycle.json")["frames"][k]["compute_cycles"]);
        EXPECT_EQ(report("fast.json")["frames"][k]["compute_cycles"],
                  report("analytic.json")["frames"][k]["compute_cycles"]);
    }
}

TEST_F(CliGrid, FixedPointGridBoardsKeepTheirFormatsPairs) {
    ASSERT_EQ(run(spheres(2000, 1) + "--format fixed12 --pairs-out all.csv").status, 0);
    const Result r = run(spheres(2000, 1) + "--format fixed12 -c board.algorithm=grid --pairs-out grid.csv");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "grid.csv"), slurp(dir_ / "all.csv"));
}

// --algorithm grid is board.algorithm's flag: the same run as -c board.algorithm=grid, and the
// report says where the setting came from.
TEST_F(CliGrid, TheAlgorithmFlagChoosesTheGridBoard) {
    ASSERT_EQ(run(spheres(2000, 1) + "-c board.algorithm=grid --pairs-out c.csv --report c.json").status, 0);
    const Result r = run(spheres(2000, 1) + "--algorithm grid --pairs-out flag.csv --report flag.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "flag.csv"), slurp(dir_ / "c.csv"));
    const json setting = report("flag.json")["config"]["settings"]["board.algorithm"];
    EXPECT_EQ(setting["value"], "grid");
    EXPECT_EQ(setting["origin"], "flag --algorithm");
    EXPECT_EQ(report("flag.json")["frames"][0]["compute_cycles"], report("c.json")["frames"][0]["compute_cycles"]);
    expect_refusal(run(spheres(20, 1) + "--algorithm tree"), "cdvp run: --algorithm: ");
}

// The clocked grid board's waveforms show its sequencer's passes.
TEST_F(CliGrid, WaveformsShowTheSequencer) {
    ASSERT_EQ(run("run --scene spheres --objects 60 --frames 1 --quiet --m 2 -c board.algorithm=grid --vcd w.vcd").status,
              0);
    const std::string vcd = slurp(dir_ / "w.vcd");
    for (const char* signal : {" pass ", " bounds ", " count ", " scan ", " place ", " cells ", " box ", " cell ",
                               " loading ", " wait "}) {
        EXPECT_NE(vcd.find(signal), std::string::npos) << signal;
    }
}

TEST_F(CliGrid, ScenesPastTheCellBufferOrTheSsramAreRefused) {
    // Two halves of 2m copies of six coordinates: 12 m block RAMs at a cell of 512 boxes; 144 hold m = 12.
    expect_refusal(run(spheres(2000, 1) + "--m 13 -c board.algorithm=grid"),
                   "cdvp run: " + preset("adm-xrc-ii") +
                       ": device.block_rams: 144 block RAMs are too few for the grid board's cell buffer at --m 13 "
                       "and 512 boxes (the default of board.grid.cell_capacity): it needs 6 x 2m x ceil(C/512) = 156");
    ASSERT_EQ(run(spheres(2000, 1) + "--m 12 -c board.algorithm=grid").status, 0);
    expect_refusal(run(spheres(2000, 1) + "-c board.algorithm=grid -c device.ssram_words=3000"),
                   "cdvp run: -c device.ssram_words: 3000 words a bank in 6 SSRAM banks (18000 words) are too few "
                   "for the grid board at 2000 objects (--objects): its boxes, count table, large list and pair "
                   "buffer");
    expect_refusal(run(spheres(100, 1) + "-c board.algorithm=grid -c device.ssram_banks=0"),
                   "cdvp run: -c device.ssram_banks: the device has no off-chip SSRAM (0 banks); the grid board");
    ASSERT_EQ(run(spheres(2000, 1) + "-c board.algorithm=grid -c device.ssram_words=3000 --ignore-capacity").status, 0)
        << "--ignore-capacity explores a larger memory";
    expect_refusal(run(spheres(100, 1) + "-c board.algorithm=grid -c board.grid.dims=300"),
                   "cdvp run: -c board.grid.dims: expected an integer from 0 to 256, got '300'");
    expect_refusal(run(spheres(100, 1) + "-c board.algorithm=grid -c device.ssram_banks=3 --fidelity rtl"),
                   "cdvp run: --fidelity rtl at 100 objects (--objects): fidelity rtl: the grid board RTL reads a box "
                   "from six SSRAM banks in one slot (q = 1); cycles_per_box is 2 (device.ssram_banks below 6)");
    EXPECT_EQ(files(), std::vector<std::string>{}) << "a refused run leaves no output";
}

// A refusal a setting causes names that setting: a grid too large for the
// SSRAM names board.grid.dims and the largest that fits, not the objects or
// the pair buffer; a cell size the board's float32 cannot hold (it would be 0,
// the fitted grid, while the report recorded the value) is refused naming the
// setting and the range.
TEST_F(CliGrid, ARefusalCausedByAGridSettingNamesIt) {
    const Result large = run(spheres(40, 1) + "-c board.algorithm=grid -c board.grid.dims=256");
    expect_refusal(large, "cdvp run: -c board.grid.dims: a grid of 256^3 cells needs a count table of 3G^3 = 50331648 "
                          "words, which with the ");
    EXPECT_NE(large.err.find(" words of the boxes, large list and pair buffer at 40 objects (--objects) is more than "
                             "the 3145728 words of SSRAM (6 banks ("),
              std::string::npos)
        << large.err;
    EXPECT_NE(large.err.find("expected at most "), std::string::npos) << large.err;
    EXPECT_NE(large.err.find(" cells a side, or 0 (fitted); --ignore-capacity runs it anyway\n"), std::string::npos)
        << large.err;
    const std::size_t at = large.err.find("expected at most ") + 17;
    const std::string largest = large.err.substr(at, large.err.find(' ', at) - at);
    ASSERT_EQ(run(spheres(40, 1) + "-c board.algorithm=grid -c board.grid.dims=" + largest).status, 0)
        << "the largest it names fits";
    for (const char* tiny : {"1e-50", "1e-40", "-0"}) {
        SCOPED_TRACE(tiny);
        const Result r = run(spheres(40, 1) + "-c board.algorithm=grid -c board.grid.cell_size=" + tiny);
        if (std::string(tiny) == "-0") {
            EXPECT_EQ(r.status, 0) << r.err;
            continue;
        }
        expect_refusal(r, "cdvp run: -c board.grid.cell_size: expected 0 or 1.17549e-38 to 1e+30 coordinate units (the "
                          "board holds it as a float32, whose least normal value is about 1.2e-38), got '" +
                              std::string(tiny) + "'\n");
    }
    write("c.toml", "[board.grid]\ncell_size = 1e-45\n");
    expect_refusal(run(spheres(40, 1) + "-c board.algorithm=grid --config c.toml"),
                   "cdvp run: c.toml:2: board.grid.cell_size: expected 0 or 1.17549e-38 to 1e+30");
    ASSERT_EQ(run(spheres(40, 1) + "-c board.algorithm=grid -c board.grid.cell_size=1e-30").status, 0);
    EXPECT_EQ(files(), std::vector<std::string>{"c.toml"}) << "a refused run leaves no output";
}

}  // namespace
}  // namespace cdvp::test
