// A sweep's analytic points run inside the sweep's process (no child per
// point) and are rows like any other: the same columns, the fast engine's
// pairs, refusals with their reasons, resumed without running again; and
// compact records (--record compact).
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

// Compact rows are the full rows' figures: the same values in the same
// columns, for points run in process (analytic) and as children (fast), no
// report kept and no settings columns; refusals keep their reasons.
TEST_F(Cli, SweepCompactRowsAreTheFullRowsFiguresWithoutReports) {
    const std::string grid = "sweep --board adm-xrc-ii --fidelity fast,analytic --set m=2,32 --set objects=40,300 "
                             "--set seed=1,2 --frames 3 --baseline soa --no-plots -q";
    ASSERT_EQ(run(grid + " --out full").status, 0);
    const Result r = run(grid + " --out compact --record compact");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto full = rows_of(slurp(dir_ / "full" / "sweep.csv"));
    const auto compact = rows_of(slurp(dir_ / "compact" / "sweep.csv"));
    ASSERT_EQ(compact.size(), full.size());
    std::size_t ok = 0;
    for (std::size_t k = 0; k < compact.size(); ++k) {
        const auto &c = compact[k], &f = full[k];
        EXPECT_EQ(c.at("status"), f.at("status")) << c.at("point");
        EXPECT_EQ(c.at("reason"), f.at("reason")) << c.at("point");
        for (const auto& [column, value] : c) {
            EXPECT_NE(column.rfind("config.", 0), 0u) << "no settings columns in a compact row: " << column;
            if (column == "checksum" || column == "point_wall_s" || column.find("_host_ns") != std::string::npos ||
                column.find("_speedup") != std::string::npos || column.find("_timing_") != std::string::npos ||
                (column.find("_energy_") != std::string::npos && column.rfind("mean_", 0) != 0 &&
                 column.rfind("median_", 0) != 0)) {
                continue;  // measured
            }
            EXPECT_EQ(value, f.count(column) ? f.at(column) : "(none)") << c.at("point") << " " << column;
        }
        if (c.at("status") != "ok") continue;
        ++ok;
        for (const char* column : {"median_pairs", "median_total_ns", "median_compute_cycles", "median_upload_ns",
                                   "median_readback_ns", "mean_total_ns", "soa_speedup", "median_extra_pairs"}) {
            EXPECT_FALSE(c.at(column).empty()) << c.at("point") << " " << column;
        }
    }
    EXPECT_EQ(ok, 8u) << "m = 32 is refused, m = 2 runs";
    EXPECT_TRUE(fs::is_empty(dir_ / "compact" / "points")) << "a compact record keeps no report";
    EXPECT_LT(fs::file_size(dir_ / "compact" / "sweep.csv") * 4, fs::file_size(dir_ / "full" / "sweep.csv"));
}

// A compact sweep resumes, holds its rows to their checksums and refuses to
// be continued as a full one; its shards merge, but not with a full shard.
TEST_F(Cli, SweepCompactRecordResumesMergesAndRefusesAnotherRecord) {
    const std::string grid = "sweep --board adm-xrc-ii --fidelity analytic --set m=1:4:+1 --set objects=50,400 "
                             "--frames 2 --no-plots -q --record compact";
    ASSERT_EQ(run(grid + " --out whole").status, 0);
    const Result again = run(grid + " --out whole");
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(slurp(dir_ / "whole" / "sweep.csv").empty(), false);
    expect_refusal(run("sweep --board adm-xrc-ii --fidelity analytic --set m=1:4:+1 --set objects=50,400 --frames 2 "
                       "--no-plots -q --out whole"),
                   "cdvp sweep: --out: whole holds another sweep (--record compact, not full)");
    expect_refusal(run("sweep --board adm-xrc-ii --set m=1 --out x --record bogus"),
                   "cdvp sweep: --record: expected full or compact, got 'bogus'");
    EXPECT_FALSE(fs::exists(dir_ / "x"));
    // An edited figure does not match its checksum.
    std::string table = slurp(dir_ / "whole" / "sweep.csv");
    const auto rows = rows_of(table);
    const std::string total = rows[1].at("median_total_ns");
    table.replace(table.find("," + total + ","), total.size() + 2, ",1" + total + ",");
    write("whole/sweep.csv", table);
    const Result edited = run(grid + " --out whole");
    expect_refusal(edited, "cdvp sweep: whole/sweep.csv:3: field 'checksum': does not match the row (");
    // Shards merge into the whole sweep's rows.
    ASSERT_EQ(run(grid + " --out s1 --shard 1/2").status, 0);
    ASSERT_EQ(run(grid + " --out s2 --shard 2/2").status, 0);
    const Result merged = run("merge --out merged -q s1 s2");
    ASSERT_EQ(merged.status, 0) << merged.err;
    const auto merged_rows = sweep_rows(slurp(dir_ / "merged" / "sweep.csv"), true);
    ASSERT_EQ(run(grid + " --out fresh").status, 0);
    EXPECT_EQ(merged_rows, sweep_rows(slurp(dir_ / "fresh" / "sweep.csv"), true));
    ASSERT_EQ(run("sweep --board adm-xrc-ii --fidelity analytic --set m=1:4:+1 --set objects=50,400 --frames 2 "
                  "--no-plots -q --out f2 --shard 2/2")
                  .status,
              0);
    const Result mixed = run("merge --out mixed -q s1 f2");
    EXPECT_EQ(mixed.status, 2) << mixed.err;
    EXPECT_NE(mixed.err.find("(--record compact, not full)"), std::string::npos) << mixed.err;
}

// Points in one process share scenes and pairs: each row is what the point
// gives run alone.
TEST_F(Cli, SweepAnalyticPointsSharingScenesAndPairsGiveWhatEachGivesAlone) {
    const Result r = run("sweep --board adm-xrc-ii --fidelity analytic --set m=1,8,24 --set seed=1,2 --objects 500 "
                         "--frames 4 --format fixed12 --no-plots -q --out res");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = rows_of(slurp(dir_ / "res" / "sweep.csv"));
    ASSERT_EQ(rows.size(), 6u);
    for (const auto& row : rows) {
        const Result alone = run("run --scene spheres --board adm-xrc-ii --fidelity analytic --m " + row.at("m") + " --seed " +
                                 row.at("seed") + " --objects 500 --frames 4 --format fixed12 -q --report alone.json");
        ASSERT_EQ(alone.status, 0) << alone.err;
        auto frames = [](const std::string& text) {
            nlohmann::json f = nlohmann::json::parse(text).at("frames");
            for (auto& frame : f) frame.erase("sim_wall_native_ns");
            return f;
        };
        EXPECT_EQ(frames(slurp(dir_ / "res" / "points" / (row.at("point") + ".json"))), frames(slurp(dir_ / "alone.json")))
            << row.at("point");
    }
}

}  // namespace
}  // namespace cdvp::test
