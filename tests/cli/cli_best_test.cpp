// --baseline best end to end: the candidates for the frames' size are
// timed, each found the board's pairs, the fastest is named in the report
// and the summary, and a sweep repeats its figures under best_ beside the
// name of the baseline that was fastest at each point (docs/baselines.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

using nlohmann::json;

class CliBest : public Cli {};

TEST_F(CliBest, ARunTimesTheCandidatesAndNamesTheFastest) {
    const Result r = run("run --board pcie-gen3-x8 --scene heavy --objects 600 --frames 4 --warmup 1 --threads 2 "
                         "--baseline best,sap --report r.json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json report = report_of(dir_ / "r.json");
    EXPECT_EQ(report["config"]["baselines"], json({"prune", "hgrid", "prune_mt", "hgrid_mt", "sap"}));
    const json& summary = report["summary"];
    const std::string best = summary["best_software"];
    double least = 1e300;
    std::string fastest;
    for (const auto& [name, b] : summary["baselines"].items()) {
        if (b["mean_host_ns"].get<double>() < least) least = b["mean_host_ns"], fastest = name;
    }
    EXPECT_EQ(best, fastest);
    EXPECT_NE(r.out.find("fastest software: " + best + ","), std::string::npos) << r.out;
}

// From 500,000 boxes a frame box pruning is no candidate.
TEST_F(CliBest, BoxPruningLeavesTheCandidatesAtHalfAMillionBoxes) {
    const Result r = run("run --board alveo-u250 -c board.algorithm=grid --fidelity analytic --scene spheres "
                         "--objects 500000 --frames 1 --warmup 0 --threads 1 --baseline best --report r.json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(report_of(dir_ / "r.json")["config"]["baselines"], json({"hgrid"}));
}

TEST_F(CliBest, BestTwiceOrAnUnknownNameIsRefusedInOneLine) {
    const Result twice = run("run --scene spheres --objects 20 --frames 2 --baseline best,sap,best");
    EXPECT_EQ(twice.status, 2);
    EXPECT_EQ(twice.err, "cdvp run: --baseline: 'best' given twice\n");
    const Result unknown = run("run --scene spheres --objects 20 --frames 2 --baseline bets");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_EQ(unknown.err.rfind("cdvp run: --baseline: unknown baseline 'bets'; expected one of: sap,", 0), 0u) << unknown.err;
    EXPECT_NE(unknown.err.find(", ode_sap, or best\n"), std::string::npos) << unknown.err;
}

TEST_F(CliBest, ASweepRowCarriesTheFastestUnderBest) {
    const Result r = run("sweep --board adm-xrc-ii --set objects=200,400 --frames 3 --warmup 1 --baseline best,sap "
                         "--no-plots -q --out s");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = sweep_rows(slurp(dir_ / "s" / "sweep.csv"), false);
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) {
        const std::string best = row.at("best_baseline");
        ASSERT_TRUE(best == "prune" || best == "hgrid" || best == "sap") << best;
        EXPECT_EQ(row.at("best_speedup"), row.at(best + "_speedup"));
        EXPECT_EQ(row.at("best_energy_ratio"), row.at(best + "_energy_ratio"));
        EXPECT_LE(std::stod(row.at("best_mean_host_ns")), std::stod(row.at("sap_mean_host_ns")));
    }
}

}  // namespace
}  // namespace cdvp
