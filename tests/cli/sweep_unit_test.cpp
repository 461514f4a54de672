// The sweep's table and figures as plain C++: rows built from reports and
// read back, crossovers (the grid itself: sweep_grid_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/run/report_summary.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_plots.h"
#include "sw/study/sweep_table.h"

namespace cdvp {
namespace {

// A report as cdvp run writes it: four frames, the first a warm-up, and the
// summary over the other three in the report's own schema.
nlohmann::json report(double board_ns, double sap_ns) {
    nlohmann::json frames = nlohmann::json::array();
    for (int k = 0; k < 4; ++k) {
        const double total = k == 0 ? 10 * board_ns : board_ns + k;  // the first frame is left out
        frames.push_back({{"frame", k}, {"pairs", 10 + k}, {"total_ns", total}, {"sim_wall_native_ns", 5.0},
                          {"baselines", {{"sap", {{"native_ns", sap_ns / 4}, {"host_ns", sap_ns + k}}}}}});
    }
    ReportSummary summary;
    summary.frames = 4;
    summary.warmup_frames = 1;
    summary.frames_in_means = 3;
    summary.total_ns = {board_ns + 2, board_ns + 2, board_ns + 3, board_ns + 3};
    summary.mean_phase_ns.back() = board_ns + 2;
    summary.sim_wall_native_ns = {5, 5, 5, 5};
    BaselineSummary& sap = summary.baselines["sap"];
    sap.host_ns = {sap_ns + 2, sap_ns + 2, sap_ns + 3, sap_ns + 3};
    sap.native_ns = sap.host_ns.scaled(0.25);
    sap.host_factor = 4;
    sap.speedup = sap.host_ns.mean / summary.total_ns.mean;
    return {{"config", {{"command_line", "cdvp run --report out/points/p.json"}, {"m", 8}, {"board", "b"}, {"baselines", {"sap"}}, {"bus", {{"width", 32}}}}},
            {"frames", frames},
            {"summary", to_json(summary)}};
}

TEST(SweepTable, RowsHoldSettingsMediansAfterTheFirstFrameAndSpeedups) {
    const Grid grid(std::vector<Axis>{{"objects", {"50", "100"}}});
    SweepTable table(grid);
    table.add(1, report_row(grid, grid.point(1), report(100, 300).dump(), 0.5));
    table.add(0, failed_row(grid, grid.point(0), PointStatus::kRefused, "m=8 needs \"48\" block RAMs, the device has 6", 0.25));
    const RowView row = table.row(1);
    EXPECT_EQ(row.get("status"), "ok");
    EXPECT_EQ(row.get("objects"), "100");
    EXPECT_EQ(row.get("config.m"), "8");
    EXPECT_EQ(row.get("config.baselines"), "sap");
    EXPECT_EQ(row.get("config.bus.width"), "32");
    EXPECT_EQ(row.get("config.command_line"), "") << "it names the report's path, which differs between shards";
    EXPECT_EQ(row.get("frames_in_medians"), "3");
    EXPECT_EQ(row.get("median_total_ns"), "102");  // frames 1..3: 101, 102, 103
    EXPECT_EQ(row.get("median_pairs"), "12");
    EXPECT_EQ(row.get("median_sim_wall_native_ns"), "5");
    // The summary's means over the frames after the first (301..303 against
    // the board's 101..103).
    EXPECT_EQ(row.get("sap_mean_host_ns"), "302");
    EXPECT_NEAR(std::stod(row.get("sap_speedup")), 302.0 / 102.0, 1e-9);
    EXPECT_EQ(row.get(kChecksumColumn).size(), 16u);
    EXPECT_EQ(table.columns()[4], kChecksumColumn);
    EXPECT_EQ(table.columns()[5], "format_version");
    EXPECT_EQ(row.get("format_version"), std::to_string(kSweepFormatVersion));
    EXPECT_EQ(table.row(0).get("format_version"), std::to_string(kSweepFormatVersion)) << "a refused point's row too";
    EXPECT_EQ(table.columns()[6], "objects");
    EXPECT_TRUE(is_measured_column(table.columns().back()));
    EXPECT_EQ(table.row(0).get("reason"), "m=8 needs \"48\" block RAMs, the device has 6");
    const std::vector<std::vector<std::string>> lines = parse_csv(table.csv(), "sweep.csv");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[1][3], "m=8 needs \"48\" block RAMs, the device has 6") << "a quoted reason survives the CSV";
    EXPECT_EQ(lines[2][0], "objects-100");
}

TEST(SweepTable, BaselinesComeFromTheReportsSummaryAndItsWarmUpIsLeftOut) {
    const Grid grid(std::vector<Axis>{{"objects", {"50"}}});
    nlohmann::json with_summary = report(100, 300);
    ReportSummary summary = summary_from_json(with_summary["summary"], "the test's report");
    summary.warmup_frames = 2;
    summary.frames_in_means = 2;
    summary.too_few_frames = true;
    summary.total_ns = {102.5, 102.5, 102.99, 103};
    summary.mean_phase_ns.back() = 102.5;
    summary.load_average_end = {0.5, 0.25, 0.125};
    BaselineSummary& sap = summary.baselines["sap"];
    sap.host_ns = {290.0, 280.0, 310.0, 320.0};
    sap.native_ns = {72.5, 70.0, 77.5, 80.0};
    sap.host_factor = 4.0;
    sap.speedup = 2.5;
    with_summary["summary"] = to_json(summary);
    const Row row = report_row(grid, grid.point(0), with_summary.dump(), 0.5).values;
    EXPECT_EQ(row.at("frames_in_medians"), "2");
    EXPECT_EQ(row.at("median_total_ns"), "102.5");  // frames 2 and 3: 102, 103
    EXPECT_EQ(row.at("too_few_frames"), "true");
    EXPECT_EQ(row.at("sap_mean_host_ns"), "290");
    EXPECT_EQ(row.at("sap_p50_host_ns"), "280");
    EXPECT_EQ(row.at("sap_p99_host_ns"), "310");
    EXPECT_EQ(row.at("sap_max_host_ns"), "320");
    EXPECT_EQ(row.at("sap_host_factor"), "4");
    EXPECT_EQ(row.at("sap_speedup"), "2.5");
    EXPECT_EQ(row.at("mean_total_ns"), "102.5");
    EXPECT_EQ(row.at("max_total_ns"), "103");
    EXPECT_EQ(row.at("load_average_end"), "0.5+0.25+0.125");
    EXPECT_EQ(row.count("sap_mean_native_ns"), 0u) << "the native figures stay in the report";
    EXPECT_TRUE(is_measured_column("sap_p99_host_ns"));
    EXPECT_TRUE(is_measured_column("median_sim_wall_native_ns"));
    EXPECT_TRUE(is_measured_column("config.provenance.load_average_start"));
    EXPECT_TRUE(is_measured_column("load_average_end"));
    EXPECT_FALSE(is_measured_column("mean_total_ns")) << "simulated: the same on every run";
    EXPECT_FALSE(is_measured_column("sap_host_factor")) << "the profile's, the same on every run";
}

TEST(SweepFigures, CrossoverIsInterpolatedInLogNOrMeasuredAtTheSmallestN) {
    const Grid grid(std::vector<Axis>{{"m", {"1", "8"}}, {"objects", {"100", "400"}}});
    SweepTable table(grid);
    // m=1 never wins; m=8 goes from 0.5x at 100 to 2x at 400: crossover at 100 * 4^(1/3).
    // In energy m=8 goes from 0.4x to 1.6x: crossover at 100 * 4^(1/2).
    const double speedups[4] = {0.1, 0.2, 0.5, 2.0};
    for (std::size_t k = 0; k < 4; ++k) {
        PointRow row = failed_row(grid, grid.point(k), PointStatus::kOk, "", 0.5);
        row.values["status"] = "ok";
        row.values["config.board"] = "b";
        row.values["mean_total_ns"] = "1000";
        row.values["sap_mean_host_ns"] = std::to_string(1000 * speedups[k]);
        row.values["sap_speedup"] = std::to_string(speedups[k]);
        row.values["sap_energy_ratio"] = std::to_string(0.8 * speedups[k]);
        table.add(k, row);
    }
    const FigurePlan plan = plan_figures(grid, table);
    std::string crossover;
    for (const Figure& f : plan.figures) {
        if (f.file == "crossover.csv") crossover = f.data;
    }
    EXPECT_NE(crossover.find("b,1,sap,,none,clean,,none\n"), std::string::npos) << crossover;
    const std::size_t at = crossover.find("b,8,sap,");
    ASSERT_NE(at, std::string::npos) << crossover;
    EXPECT_NEAR(std::stod(crossover.substr(at + 8)), 100 * std::cbrt(4.0), 1e-6);
    EXPECT_NE(crossover.find("interpolated"), std::string::npos);
    const std::size_t energy = crossover.find(",interpolated,clean,", at);
    ASSERT_NE(energy, std::string::npos) << crossover;
    EXPECT_NEAR(std::stod(crossover.substr(energy + 20)), 200, 1e-6) << crossover;
}

TEST(SweepFigures, PlotsAgainstNAreSkippedWithANoteWithoutAnObjectsAxis) {
    const Grid grid(std::vector<Axis>{{"m", {"1", "2"}}});
    SweepTable table(grid);
    PointRow row = report_row(grid, grid.point(0), report(100, 300).dump(), 0.1);
    table.add(0, row);
    const FigurePlan plan = plan_figures(grid, table);
    bool noted = false;
    for (const std::string& note : plan.notes) noted |= note.find("objects (or scene.objects) is not an axis") != std::string::npos;
    EXPECT_TRUE(noted);
    for (const Figure& f : plan.figures) EXPECT_EQ(f.file.rfind("time-", 0), std::string::npos) << f.file;
}

TEST(SweepFigures, AnotherVaryingAxisDrawsLinesOfItsOwnAndFitCsvGivesTheLargestMPerVariant) {
    const Grid grid(std::vector<Axis>{{"format", {"float32", "fixed16"}}, {"m", {"8", "24"}}, {"objects", {"100", "800"}}});
    SweepTable table(grid);
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const Point point = grid.point(k);
        PointRow row = failed_row(grid, point, PointStatus::kOk, "", 0.5);
        const Row axes = row.values;
        const bool fixed = axes.at("format") == "fixed16";
        const bool large = axes.at("objects") == "800";
        row.values["status"] = "ok";
        row.values["config.board"] = "b";
        row.values["mean_total_ns"] = std::to_string(1000 + k);
        row.values["median_total_ns"] = std::to_string(1000 + k);
        // Narrower words fit more lanes; they add extra pairs.
        row.values["config.resources.largest_m"] = large ? (fixed ? "24" : "12") : "24";
        row.values["median_reference_pairs"] = "200";
        row.values["median_extra_pairs"] = fixed ? "50" : "0";
        table.add(k, row);
    }
    const FigurePlan plan = plan_figures(grid, table);
    std::string fit;
    std::set<std::string> time;
    bool frontier = false;
    for (const Figure& f : plan.figures) {
        if (f.file == "fit.csv") fit = f.data;
        if (f.file == "time-b.png") {
            for (const PlotSeries& s : f.series) time.insert(s.title);
        }
        frontier |= f.file == "lanes-extra-b.png";
    }
    EXPECT_EQ(time.count("m=8 format=fixed16"), 1u);
    EXPECT_EQ(time.count("m=24 format=float32"), 1u);
    EXPECT_EQ(fit.substr(0, fit.find('\n')), "board,format,objects,largest_m,lanes,extra_pair_share,board_median_total_ns");
    // float32 at N=800: m=12 was not swept, so no time; fixed16 at N=800: m=24 ran (point 7).
    EXPECT_NE(fit.find("\nb,float32,800,12,23,0,\n"), std::string::npos) << fit;
    EXPECT_NE(fit.find("\nb,fixed16,800,24,47,0.25,1007\n"), std::string::npos) << fit;
    EXPECT_TRUE(frontier);
}

}  // namespace
}  // namespace cdvp
