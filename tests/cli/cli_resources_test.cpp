// What fits on the device: the report's resources from the synthesis-backed
// model, the refusal naming the resource that overflows and the largest m
// that fits, --ignore-capacity, and the resources as sweep columns.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "models/resources/resource_model.h"
#include "tests/cli/cli_support.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliResources : public Cli {
protected:
    std::string spheres(uint32_t objects) const {
        return "run --scene spheres --objects " + std::to_string(objects) + " --frames 1 --quiet --board adm-xrc-ii ";
    }
    json resources() const { return report_of(dir_ / "r.json")["config"]["resources"]; }
};

TEST_F(CliResources, ThePapersBoardAt500ObjectsFillsItsBlockRamsAtM24) {
    const Result r = run(spheres(500) + "--m 24 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json res = resources();
    EXPECT_EQ(res["device"], "XC2V6000-4");
    EXPECT_EQ(res["family"], "xc2v");
    EXPECT_EQ(res["block_rams"]["used"], 144.0);  // 6 x 24 x ceil(500/512): every block RAM
    EXPECT_EQ(res["block_rams"]["available"], 144.0);
    EXPECT_EQ(res["pair_fifo_memory"], "distributed");  // no block RAM is left for the FIFO
    EXPECT_EQ(res["largest_m"], 24);
    EXPECT_TRUE(res["fits"].get<bool>());
    const double lane_luts = SynthesisTable::stored().lane("xc2v", "float32").luts;
    EXPECT_EQ(res["pieces"]["lanes"]["luts"], 47 * lane_luts);
    EXPECT_GT(res["luts"]["used"].get<double>(), 47 * lane_luts);
    EXPECT_LT(res["luts"]["utilisation"].get<double>(), 1.0);
    // A smaller m leaves block RAMs for the FIFO.
    ASSERT_EQ(run(spheres(500) + "--m 8 --report r.json").status, 0);
    EXPECT_EQ(resources()["pair_fifo_memory"], "block_ram");
}

TEST_F(CliResources, ABoardOverItsLutsIsRefusedNamingTheResourceAndTheLargestM) {
    const std::string device = " -c device.block_rams=1000 -c device.luts=20000";
    // What the model says of m = 32 on this device, run anyway.
    ASSERT_EQ(run(spheres(200) + "--m 32 --ignore-capacity --report r.json" + device).status, 0);
    const json explored = resources();
    EXPECT_FALSE(explored["fits"].get<bool>());
    EXPECT_GT(explored["luts"]["used"].get<double>(), 20000);
    const int largest = explored["largest_m"];
    ASSERT_GT(largest, 0);
    ASSERT_LT(largest, 32);
    const Result r = run(spheres(200) + "--m 32" + device);
    expect_refusal(r, "cdvp run: -c device.luts: 20000 LUTs are too few for --m 32 at 200 objects (--objects)");
    EXPECT_NE(r.err.find("(largest m that fits: " + std::to_string(largest) + "; --ignore-capacity runs it"),
              std::string::npos)
        << r.err;
    // The largest m that fits does fit, and one more does not.
    EXPECT_EQ(run(spheres(200) + "--m " + std::to_string(largest) + device).status, 0);
    EXPECT_EQ(run(spheres(200) + "--m " + std::to_string(largest + 1) + device).status, 2);
}

TEST_F(CliResources, BlockRamsTooFewAreRefusedAndIgnoreCapacityRunsAnyway) {
    const Result refused = run(spheres(500) + "--m 30");
    expect_refusal(refused, "cdvp run: " + preset("adm-xrc-ii") +
                                ": device.block_rams: 144 block RAMs are too few for --m 30 at 500 objects");
    EXPECT_NE(refused.err.find("(largest m that fits: 24; --ignore-capacity runs it anyway)"), std::string::npos)
        << refused.err;
    const Result explored = run(spheres(500) + "--m 30 --ignore-capacity --report r.json");
    ASSERT_EQ(explored.status, 0) << explored.err;
    const json res = resources();
    EXPECT_FALSE(res["fits"].get<bool>());
    EXPECT_EQ(res["block_rams"]["used"], 180.0);
    EXPECT_EQ(report_of(dir_ / "r.json")["config"]["settings"]["run.ignore_capacity"]["value"], "yes");
}

TEST_F(CliResources, WithoutADeviceNothingIsCostedOrBounded) {
    const Result r = run("run --scene spheres --objects 600 --frames 1 --quiet --m 32 --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(report_of(dir_ / "r.json")["config"].contains("resources"));
}

TEST_F(CliResources, SweepRowsCarryTheUtilisationOfEachResource) {
    const Result r = run("sweep --board adm-xrc-ii --set m=4,24 --objects 100 --frames 2 --out out -q --no-plots");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string csv = slurp(dir_ / "out" / "sweep.csv");
    for (const char* column : {"config.resources.luts.utilisation", "config.resources.flip_flops.utilisation",
                               "config.resources.block_rams.utilisation", "config.resources.largest_m"}) {
        EXPECT_NE(csv.substr(0, csv.find('\n')).find(column), std::string::npos) << column;
    }
}

}  // namespace
}  // namespace cdvp::test
