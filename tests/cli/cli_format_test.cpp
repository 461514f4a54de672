// Comparator number formats through the CLI: --format, the report's extra
// pairs against the float32 reference, refusals, sweeps over formats, and the
// reference check that makes a lost pair a fault.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sw/run/format_reference.h"
#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_table.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliFormat : public Cli {
protected:
    json report() const { return report_of(dir_ / "r.json"); }
};

TEST_F(CliFormat, AFixedFormatRunsAndReportsExtraPairsAgainstTheFloat32Reference) {
    const std::string scene = "run --scene spheres --objects 1500 --frames 3 --board adm-xrc-ii --m 4 ";
    ASSERT_EQ(run(scene + "--quiet --report r.json").status, 0);
    const json float32 = report();
    EXPECT_EQ(float32["config"]["format"], "float32");
    EXPECT_EQ(float32["summary"]["extra_pairs"], 0);
    EXPECT_EQ(float32["summary"]["reference_pairs"], float32["summary"]["pairs"]);

    const Result r = run(scene + "--format fixed8 --report r.json --baseline soa");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("(7 fixed8 lanes)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fixed8: "), std::string::npos) << r.out;
    const json fixed = report();
    EXPECT_EQ(fixed["config"]["format"], "fixed8");
    EXPECT_EQ(fixed["config"]["resources"]["format"], "fixed8");
    EXPECT_EQ(fixed["summary"]["reference_pairs"], float32["summary"]["reference_pairs"])
        << "the reference is the float32 board's pairs, and the scene evolves on them alone";
    const uint64_t extra = fixed["summary"]["extra_pairs"];
    EXPECT_GT(extra, 0u) << "8-bit codes over a whole scene are coarse";
    EXPECT_EQ(fixed["summary"]["pairs"].get<uint64_t>(), fixed["summary"]["reference_pairs"].get<uint64_t>() + extra);
    EXPECT_GT(fixed["summary"]["extra_readback_ns"].get<double>(), 0.0);
    EXPECT_GT(fixed["summary"]["extra_driver_ns"].get<double>(), 0.0);
    for (const json& frame : fixed["frames"]) {
        EXPECT_EQ(frame["pairs"].get<uint64_t>(), frame["reference_pairs"].get<uint64_t>() + frame["extra_pairs"].get<uint64_t>());
        EXPECT_LE(frame["extra_readback_ns"].get<double>(), frame["readback_ns"].get<double>());
    }
    // Narrow words fill deeper block RAMs: 2048 boxes a primitive instead of 512.
    EXPECT_EQ(float32["config"]["block_rams"], 6 * 4 * 3);
    EXPECT_EQ(fixed["config"]["block_rams"], 6 * 4 * 1);
    EXPECT_LT(fixed["config"]["resources"]["pieces"]["lanes"]["luts"].get<double>(),
              float32["config"]["resources"]["pieces"]["lanes"]["luts"].get<double>());
}

TEST_F(CliFormat, AFixedFormatBoardSweepingSsramTiles) {
    const std::string scene = "run --scene spheres --objects 1500 --frames 2 --board adm-xrc-ii --m 4 --quiet "
                              "-c board.memory=ssram -c board.tile_boxes=256 --report r.json ";
    const Result r = run(scene + "--format fixed16");
    ASSERT_EQ(r.status, 0) << r.err;
    const json fixed = report();
    ASSERT_EQ(run(scene).status, 0);
    const json float32 = report();
    EXPECT_EQ(fixed["summary"]["reference_pairs"], float32["summary"]["pairs"]);
    EXPECT_GE(fixed["summary"]["pairs"].get<uint64_t>(), float32["summary"]["pairs"].get<uint64_t>());
}

TEST_F(CliFormat, BothEnginesAgreeUnderAFixedFormat) {
    const std::string scene = "run --scene spheres --objects 300 --frames 2 --board adm-xrc-ii --format fixed12 --quiet ";
    ASSERT_EQ(run(scene + "--fidelity cycle --report r.json").status, 0);
    const json cycle = report();
    ASSERT_EQ(run(scene + "--fidelity fast --report r.json").status, 0);
    const json fast = report();
    for (std::size_t f = 0; f < 2; ++f) {
        for (const char* key : {"pairs", "extra_pairs", "compute_cycles", "stall_cycles", "total_ns"}) {
            EXPECT_EQ(cycle["frames"][f][key], fast["frames"][f][key]) << key;
        }
    }
}

TEST_F(CliFormat, ANarrowerFormatFitsMoreBoxesOnThePapersDevice) {
    // float32 at 2000 boxes needs 6 x 24 x 4 block RAMs; fixed8 6 x 24 x 1 = 144.
    const std::string scene = "run --scene spheres --objects 2000 --frames 1 --board adm-xrc-ii --m 24 --quiet ";
    const Result float32 = run(scene);
    EXPECT_EQ(float32.status, 2);
    EXPECT_NE(float32.err.find("device.block_rams: 144 block RAMs are too few"), std::string::npos) << float32.err;
    const Result fixed = run(scene + "--format fixed8 --report r.json");
    ASSERT_EQ(fixed.status, 0) << fixed.err;
    EXPECT_EQ(report()["config"]["resources"]["block_rams"]["used"], 144.0);
}

TEST_F(CliFormat, ABadFormatIsRefusedOnOneLine) {
    for (const char* bad : {"fixed7", "fixed33", "int16", "fixed", "float64"}) {
        const Result r = run(std::string("run --scene spheres --objects 10 --format ") + bad);
        expect_refusal(r, "cdvp run: --format", bad);
        EXPECT_NE(r.err.find("expected float32 or fixedK with K from 8 to 32, got '" + std::string(bad) + "'"),
                  std::string::npos)
            << r.err;
        expect_refusal(run(std::string("run --scene spheres --objects 10 -c board.format=") + bad), "cdvp run: -c board.format",
                       bad);
    }
}

TEST_F(CliFormat, SweepsRunOverFormats) {
    const Result r = run("sweep --board adm-xrc-ii --set format=float32,fixed8 --set objects=400 --frames 1 --out res");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = parse_csv(slurp(dir_ / "res" / "sweep.csv"), "sweep.csv");
    ASSERT_EQ(lines.size(), 3u);
    const auto& header = lines[0];
    auto at = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    EXPECT_EQ(lines[1][at("config.format")], "float32");
    EXPECT_EQ(lines[2][at("config.format")], "fixed8");
    EXPECT_EQ(lines[1][at("median_extra_pairs")], "0");
    EXPECT_GT(std::stod(lines[2][at("median_extra_pairs")]), 0.0);
    // A bad format is refused before any point runs, with the setting's own message.
    const Result bad = run("sweep --set format=float32,fixed40 --set objects=20 --out res2");
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err, "cdvp sweep: --set format: expected float32 or fixedK with K from 8 to 32, got 'fixed40'\n");
    EXPECT_FALSE(fs::exists(dir_ / "res2"));
}

// The check itself: a board that misses a pair of the float32 reference is
// caught and the pair named (no real board model loses one, so a made-up
// pair list stands in for a broken board).
TEST(FormatReference, AMissingPairIsFoundAndExtraPairsCosted) {
    const std::vector<FloatBox> boxes = {{{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {2, 1, 1}}, {{1.5f, 0, 0}, {3, 1, 1}},
                                         {{5, 5, 5}, {6, 6, 6}}};
    FramePhases phases;
    phases.readback_ns = 1000;
    FormatReference reference(NumberFormat::fixed(8), 50);
    // The float32 pairs: (0,1) touching, (1,2).
    const FormatReference::Check all = reference.check(boxes, {{0, 1}, {0, 2}, {1, 2}}, phases);
    EXPECT_FALSE(all.missing);
    EXPECT_EQ(all.reference, (PairList{{0, 1}, {1, 2}}));
    EXPECT_EQ(all.extra.extra_pairs, 1u);
    EXPECT_DOUBLE_EQ(all.extra.extra_readback_ns, 1000.0 / 3);
    EXPECT_DOUBLE_EQ(all.extra.extra_driver_ns, 50.0);
    const FormatReference::Check lost = reference.check(boxes, {{0, 1}, {0, 2}}, phases);
    ASSERT_TRUE(lost.missing);
    EXPECT_EQ(*lost.missing, (IndexPair{1, 2}));
    Frame frame;
    frame.ids = {10, 11, 12, 13};
    EXPECT_EQ(lost_pair_message(NumberFormat::fixed(8), frame, *lost.missing),
              "the fixed8 board lost the pair (11, 12) of the float32 reference");
    // Under float32 the board is its own reference.
    FormatReference same(NumberFormat::float32(), 50);
    const PairList board{{0, 1}};
    const FormatReference::Check own = same.check(boxes, board, phases);
    EXPECT_EQ(own.extra.reference_pairs, 1u);
    EXPECT_EQ(&same.kept(own, board), &board);
    EXPECT_EQ(reference.kept(all, board), all.reference);
    // A tiled board reports its pairs block by block, not in index order: the
    // check does not depend on the order, and the host keeps the board's order.
    const FormatReference::Check shuffled = reference.check(boxes, {{1, 2}, {0, 2}, {0, 1}}, phases);
    EXPECT_FALSE(shuffled.missing);
    EXPECT_EQ(shuffled.kept, (PairList{{1, 2}, {0, 1}}));
}

}  // namespace
}  // namespace cdvp::test
