// A sweep states its answer: answer.csv checked against sweep.csv's rows by a
// computation of the test's own, answer.md and the figures beside it, the
// short form on stdout (none with -q), and no answer left by a sweep that
// failed.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tests/cli/sweep_rows.h"

namespace cdvp::test {
namespace {

using Rows = std::vector<std::map<std::string, std::string>>;

// Two algorithms and two m on today's card, the software's two Bullet broad
// phases; analytic, so the points run in the sweep's process in seconds.
const std::string kGrid =
    "sweep --board alveo-u250 --fidelity analytic --set board.algorithm=all_pairs,grid --set m=2,8 "
    "--set objects=50,200,800 --frames 3 --baseline sap,dbvt";

double value(const std::map<std::string, std::string>& row, const std::string& column) {
    return std::stod(row.at(column));
}

// The row of sweep.csv of least mean frame time at N.
const std::map<std::string, std::string>& fastest_at(const Rows& sweep, const std::string& n) {
    const std::map<std::string, std::string>* best = nullptr;
    for (const auto& row : sweep) {
        if (row.at("objects") != n || row.at("status") != "ok") continue;
        if (best == nullptr || value(row, "mean_total_ns") < value(*best, "mean_total_ns")) best = &row;
    }
    EXPECT_NE(best, nullptr) << n;
    return *best;
}

// The smallest N from which the speedups stay at 1 or above, interpolated as
// a power of N after the last N below 1; 0 when the largest N is below 1.
double staying_ahead_from(const std::vector<std::pair<double, double>>& speedups) {
    std::ptrdiff_t last_below = -1;
    for (std::size_t k = 0; k < speedups.size(); ++k) {
        if (speedups[k].second < 1) last_below = static_cast<std::ptrdiff_t>(k);
    }
    if (last_below < 0) return speedups.front().first;
    if (last_below + 1 == static_cast<std::ptrdiff_t>(speedups.size())) return 0;
    const auto [n0, s0] = speedups[last_below];
    const auto [n1, s1] = speedups[last_below + 1];
    return n0 * std::pow(n1 / n0, std::log(s0) / (std::log(s0) - std::log(s1)));
}

TEST_F(Cli, SweepAnswerIsTheFastestConfigurationOfItsRowsAgainstTheFastestSoftware) {
    const Result r = run(kGrid + " --out res");
    ASSERT_EQ(r.status, 0) << r.err;
    const Rows sweep = sweep_rows(slurp(dir_ / "res" / "sweep.csv"), false);
    const Rows answer = sweep_rows(slurp(dir_ / "res" / "answer.csv"), false);
    ASSERT_EQ(answer.size(), 3u) << "a row per N of the one scene";
    std::vector<std::pair<double, double>> speedups;
    for (std::size_t k = 0; k < answer.size(); ++k) {
        const auto& a = answer[k];
        const auto& best = fastest_at(sweep, a.at("objects"));
        EXPECT_EQ(a.at("scene"), "spheres");
        EXPECT_EQ(a.at("point"), best.at("point"));
        EXPECT_EQ(a.at("algorithm"), best.at("board.algorithm"));
        EXPECT_EQ(a.at("m"), best.at("m"));
        EXPECT_EQ(a.at("format"), "float32");
        EXPECT_EQ(value(a, "board_frame_ns"), value(best, "mean_total_ns"));
        EXPECT_EQ(value(a, "board_energy_j"), value(best, "mean_energy_j"));
        const std::string software = value(best, "sap_mean_host_ns") <= value(best, "dbvt_mean_host_ns") ? "sap" : "dbvt";
        EXPECT_EQ(a.at("software"), software) << a.at("objects");
        const double speedup = value(best, software + "_mean_host_ns") / value(best, "mean_total_ns");
        EXPECT_NEAR(value(a, "speedup"), speedup, 1e-6 * speedup);
        const double energy_ratio = value(best, software + "_energy_j") / value(best, "mean_energy_j");
        EXPECT_NEAR(value(a, "energy_ratio"), energy_ratio, 1e-6 * energy_ratio);
        EXPECT_LE(value(a, "energy_ratio_low"), value(a, "energy_ratio"));
        EXPECT_GE(value(a, "energy_ratio_high"), value(a, "energy_ratio"));
        EXPECT_EQ(a.at("software_timing"), best.at(software + "_timing_quality"));
        EXPECT_EQ(a.at("clock_met"), best.at("config.resources.timing.meets_clock") == "true" ? "yes" : "no");
        // What bounds the frame: the bus's phases, the driver's, or the board's compute (no tiles, no memory waits).
        const double bus = value(best, "mean_upload_ns") + value(best, "mean_start_ns") + value(best, "mean_irq_ns") +
                           value(best, "mean_readback_ns");
        const double compute = value(best, "mean_compute_ns"), host = value(best, "mean_driver_ns");
        const std::string bound = bus >= compute && bus >= host ? "bus" : compute >= host ? "compute" : "host";
        EXPECT_EQ(a.at("bound_by"), bound) << a.at("objects");
        EXPECT_NEAR(value(a, "bus_share"), bus / (bus + compute + host), 1e-9);
        speedups.push_back({value(a, "objects"), value(a, "speedup")});
    }
    const double crossover = staying_ahead_from(speedups);
    if (crossover == 0) {
        EXPECT_EQ(answer[0].at("time_crossover_n"), "");
        EXPECT_EQ(answer[0].at("time_crossover_how"), "none");
    } else {
        EXPECT_NEAR(value(answer[0], "time_crossover_n"), crossover, 1e-6 * crossover);
    }
    for (const char* file : {"answer.md", "answer-time.png", "answer-energy.png"}) {
        EXPECT_TRUE(fs::exists(dir_ / "res" / file)) << file;
    }
    const std::string md = slurp(dir_ / "res" / "answer.md");
    EXPECT_NE(md.find("| 800 | alveo-u250 " + answer[2].at("algorithm") + " m=" + answer[2].at("m") + " float32 |"),
              std::string::npos) << md;
    // The short form follows the summary line: a header, a line an N, the crossovers.
    const std::size_t told = r.out.find("the answer (res/answer.md): ");
    ASSERT_NE(told, std::string::npos) << r.out;
    EXPECT_LT(r.out.find("cdvp sweep: 12 points"), told);
    EXPECT_NE(r.out.find("  spheres  800 ", told), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("  spheres: faster from ", told), std::string::npos) << r.out;
}

TEST_F(Cli, SweepAnswerIsWrittenQuietlyWithQAndWithoutPlots) {
    const Result r = run("sweep --board adm-xrc-ii --fidelity analytic --set m=1,4 --set objects=20,40 --frames 2 "
                         "--baseline soa --out res -q --no-plots");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "") << "-q prints nothing but errors";
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(sweep_rows(slurp(dir_ / "res" / "answer.csv"), false).size(), 2u);
    EXPECT_TRUE(fs::exists(dir_ / "res" / "answer.md"));
    EXPECT_FALSE(fs::exists(dir_ / "res" / "answer-time.png")) << "--no-plots draws no figure";
}

TEST_F(Cli, SweepThatFailsLeavesNoAnswer) {
    // gnuplot not on PATH: the figures fail, and the answer's files with them.
    fs::create_directories(dir_ / "nothing");
    const Result r = run("sweep --board adm-xrc-ii --fidelity analytic --set m=1,4 --set objects=20,40 --frames 2 "
                         "--baseline soa --out res", "PATH='" + (dir_ / "nothing").string() + "'");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("gnuplot failed"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("the answer"), std::string::npos) << r.out;
    for (const char* file : {"answer.csv", "answer.md", "answer-time.png", "crossover.csv"}) {
        EXPECT_FALSE(fs::exists(dir_ / "res" / file)) << file;
    }
    // Every point refused: nothing at all.
    const Result refused = run("sweep --board adm-xrc-ii --fidelity analytic --set m=32 --objects 600 --memory block_ram "
                               "--frames 2 --out none");
    EXPECT_EQ(refused.status, 2) << refused.err;
    EXPECT_FALSE(fs::exists(dir_ / "none" / "answer.csv"));
    EXPECT_FALSE(fs::exists(dir_ / "none" / "answer.md"));
}

}  // namespace
}  // namespace cdvp::test
