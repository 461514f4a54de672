// A sweep's analytic points run inside the sweep's process (no child per
// point) and are rows like any other: the same columns, the fast engine's
// pairs, refusals with their reasons, resumed without running again.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

std::vector<std::map<std::string, std::string>> rows_of(const std::string& csv) { return sweep_rows(csv, false); }

TEST_F(Cli, SweepAnalyticPointsMatchTheFastEnginesPairsAndExactPhases) {
    const Result r = run("sweep --board adm-xrc-ii --fidelity fast,analytic --set m=1,8 --set objects=40,300 --frames 2 "
                         "--baseline soa --out res -q --no-plots");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = rows_of(slurp(dir_ / "res" / "sweep.csv"));
    ASSERT_EQ(rows.size(), 8u);
    // fast points first (the first axis outermost), then the same grid at the analytic level.
    for (std::size_t k = 0; k < 4; ++k) {
        const auto &fast = rows[k], &analytic = rows[k + 4];
        ASSERT_EQ(fast.at("status"), "ok") << fast.at("reason");
        ASSERT_EQ(analytic.at("status"), "ok") << analytic.at("reason");
        EXPECT_EQ(analytic.at("config.fidelity"), "analytic");
        EXPECT_EQ(analytic.at("median_pairs"), fast.at("median_pairs")) << analytic.at("point");
        EXPECT_EQ(analytic.at("mean_upload_ns"), fast.at("mean_upload_ns")) << analytic.at("point");
        EXPECT_EQ(analytic.at("mean_readback_ns"), fast.at("mean_readback_ns")) << analytic.at("point");
        const double total = std::stod(fast.at("mean_total_ns"));
        EXPECT_LT(std::abs(std::stod(analytic.at("mean_total_ns")) - total), 0.05 * total) << analytic.at("point");
        EXPECT_GT(std::stod(analytic.at("soa_speedup")), 0.0) << "the baselines are timed at the analytic level too";
        EXPECT_TRUE(fs::exists(dir_ / "res" / "points" / (analytic.at("point") + ".json")));
    }
}

TEST_F(Cli, SweepRunsAnalyticPointsInItsOwnProcessAndResumesThem) {
    const std::string grid = "sweep --board adm-xrc-ii --fidelity analytic --set m=2,32 --set objects=20,40 --frames 2 "
                             "--out res --no-plots";
    const Result r = run(grid);
    ASSERT_EQ(r.status, 0) << r.err;
    // No point ran as a child (and without plots nothing else did).
    EXPECT_NE(r.out.find("4 points in res/sweep.csv: 2 ok, 2 refused, 0 faulted (4 run now; CPU time "), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(" s in the sweep, 0.000 s in its points and plots)"), std::string::npos) << r.out;
    const auto rows = rows_of(slurp(dir_ / "res" / "sweep.csv"));
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[2].at("status"), "refused");
    EXPECT_NE(rows[2].at("reason").find("block RAM"), std::string::npos) << "the run's own reason: " << rows[2].at("reason");
    EXPECT_EQ(rows[2].at("reason").rfind("cdvp run: ", 0), std::string::npos) << "without the program's name, as a child's";
    const Result again = run(grid);
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.out.find("4 points in res/sweep.csv: 2 ok, 2 refused, 0 faulted (0 run now; "), std::string::npos)
        << again.out;
}

}  // namespace
}  // namespace cdvp::test
