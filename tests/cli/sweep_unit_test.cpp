// The sweep's grid, table and figures as plain C++: lists expanded, points
// numbered and named, rows built from reports and read back, crossovers.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/cli/sweep_grid.h"
#include "sw/cli/sweep_names.h"
#include "sw/cli/sweep_plots.h"
#include "sw/cli/sweep_table.h"

namespace cdvp {
namespace {

using Values = std::vector<std::string>;

TEST(SweepList, CommaListsKeepTheirValuesAsWritten) {
    EXPECT_EQ(expand_list("a,b,c", "--board"), (Values{"a", "b", "c"}));
    EXPECT_EQ(expand_list("24", "--set m"), (Values{"24"}));
    EXPECT_EQ(expand_list("0.50,1e3", "--set x"), (Values{"0.50", "1e3"}));
}

TEST(SweepList, GeometricRangesMultiplyUpToTheEndInclusive) {
    EXPECT_EQ(expand_list("50:2000:x2", "--set objects"), (Values{"50", "100", "200", "400", "800", "1600"}));
    EXPECT_EQ(expand_list("1:16:x2", "--set m"), (Values{"1", "2", "4", "8", "16"}));
    EXPECT_EQ(expand_list("0.5:4:x2", "--set x"), (Values{"0.5", "1", "2", "4"}));
    EXPECT_EQ(expand_list("1:1:x10", "--set x"), (Values{"1"}));
    EXPECT_EQ(expand_list("0.1:1:x10", "--set x"), (Values{"0.1", "1"})) << "B is reached up to rounding";
}

TEST(SweepList, ArithmeticRangesStepUpToTheEndInclusive) {
    EXPECT_EQ(expand_list("1:24:+8", "--set m"), (Values{"1", "9", "17"}));
    EXPECT_EQ(expand_list("0:1:+0.25", "--set q"), (Values{"0", "0.25", "0.5", "0.75", "1"}));
    EXPECT_EQ(expand_list("5:5:+1", "--set q"), (Values{"5"}));
}

TEST(SweepList, ColonsAreKeptInPlainListsWithoutRanges) {
    EXPECT_EQ(expand_list("a:b:c", "--trace", false), (Values{"a:b:c"}));
}

TEST(SweepList, BadListsAreRefusedWithOneLineNamingTheList) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"", "an empty value"},          {"a,,b", "an empty value"},     {"a,", "an empty value"},
        {"1,2,1", "'1' is given twice"}, {"1:8", "expected a,b,c or"},   {"1:8:2", "expected the step"},
        {"1:8:x", "expected the step"},  {"a:8:x2", "expected numbers"}, {"8:1:x2", "A is above B"},
        {"1:8:x1", "a factor above 1"},  {"0:8:x2", "a factor above 1"}, {"1:8:+0", "an increment above 0"},
        {"1:8:+-1", "an increment above 0"}, {"1:8:x2:3", "expected a,b,c or"}, {"0x10:20:+1", "expected numbers"},
        {"1:inf:+1", "expected numbers"}, {"1:1e9:+1", "more than 100000 values"}};
    for (const auto& [list, why] : cases) {
        try {
            expand_list(list, "--set m");
            ADD_FAILURE() << list << ": accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind("--set m: '" + list + "': ", 0), 0u) << message;
            EXPECT_NE(message.find(why), std::string::npos) << list << ": " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos);
        }
    }
}

TEST(SweepSet, NamesAFlagOrADottedSetting) {
    const Axis m = parse_set("m=1,2");
    EXPECT_EQ(m.name, "m");
    EXPECT_EQ(m.values, (Values{"1", "2"}));
    EXPECT_EQ(parse_set("bus.interrupt_ns=5000:10000:x2").values, (Values{"5000", "10000"}));
    for (const char* bad : {"m", "=1,2", "M=1", "1m=2", "m x=1", "--m=1"}) {
        EXPECT_THROW(parse_set(bad), InputError) << bad;
    }
}

TEST(SweepShard, TakesEveryNthPointFromK) {
    const Shard shard = parse_shard("2/3");
    std::vector<std::size_t> runs;
    for (std::size_t k = 0; k < 8; ++k) {
        if (shard.runs(k)) runs.push_back(k);
    }
    EXPECT_EQ(runs, (std::vector<std::size_t>{1, 4, 7}));
    EXPECT_TRUE(parse_shard("1/1").whole());
    for (const char* bad : {"0/2", "3/2", "1", "1/", "/2", "a/b", "1/2/3", "-1/2", "1/0"}) {
        EXPECT_THROW(parse_shard(bad), InputError) << bad;
    }
}

TEST(SweepGrid, PointsRunRowMajorWithReadableUniqueIds) {
    const Grid grid(std::vector<Axis>{{"board", {"adm-xrc-ii", "pcie-gen3-x8"}}, {"m", {"1", "8", "24"}}, {"objects", {"50", "100"}}});
    ASSERT_EQ(grid.size(), 12u);
    const Point p = grid.point(9);  // 9 = 1*6 + 1*2 + 1: board 1, m 8, objects 100
    EXPECT_EQ(p.values, (Values{"pcie-gen3-x8", "8", "100"}));
    EXPECT_EQ(p.id, "board-pcie-gen3-x8_m-8_objects-100");
    EXPECT_EQ(grid.run_arguments(p), (Values{"--board", "pcie-gen3-x8", "--m", "8", "--objects", "100"}));
    std::set<std::string> ids;
    for (std::size_t k = 0; k < grid.size(); ++k) ids.insert(grid.point(k).id);
    EXPECT_EQ(ids.size(), grid.size());
}

TEST(SweepGrid, SettingsGoThroughDashCAndFilesAreNamedByTheirStems) {
    const Grid grid(std::vector<Axis>{{"trace", {"a/x.csv", "b/x.csv", "c/y z.csv"}}, {"bus.interrupt_ns", {"5000"}}});
    EXPECT_EQ(grid.point(0).id, "trace-x.1_bus.interrupt_ns-5000");
    EXPECT_EQ(grid.point(1).id, "trace-x.2_bus.interrupt_ns-5000");
    EXPECT_EQ(grid.point(2).id, "trace-y-z_bus.interrupt_ns-5000");
    EXPECT_EQ(grid.run_arguments(grid.point(2)), (Values{"--trace", "c/y z.csv", "-c", "bus.interrupt_ns=5000"}));
}

TEST(SweepGrid, RefusesRepeatedAxesAndNoAxes) {
    EXPECT_THROW(Grid(std::vector<Axis>{{"m", {"1"}}, {"m", {"2"}}}), InputError);
    EXPECT_THROW(Grid(std::vector<Axis>{}), InputError);
}

nlohmann::json report(double board_ns, double sap_ns) {
    nlohmann::json frames = nlohmann::json::array();
    for (int k = 0; k < 4; ++k) {
        const double total = k == 0 ? 10 * board_ns : board_ns + k;  // the first frame is left out
        frames.push_back({{"frame", k}, {"pairs", 10 + k}, {"total_ns", total}, {"sim_wall_ns", 5.0},
                          {"baselines", {{"sap", {{"ns", sap_ns / 4}, {"scaled_ns", sap_ns + k}}}}}});
    }
    return {{"config", {{"command_line", "cdvp run --report out/points/p.json"}, {"m", 8}, {"board", "b"}, {"baselines", {"sap"}}, {"bus", {{"width", 32}}}}}, {"frames", frames}};
}

TEST(SweepTable, RowsHoldSettingsMediansAfterTheFirstFrameAndSpeedups) {
    const Grid grid(std::vector<Axis>{{"objects", {"50", "100"}}});
    SweepTable table(grid);
    table.add(1, report_row(grid, grid.point(1), report(100, 300), 0.5));
    table.add(0, failed_row(grid, grid.point(0), PointStatus::kRefused, "m=8 needs \"48\" block RAMs, the device has 6", 0.25));
    const Row& row = table.rows().at(1);
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_EQ(row.at("objects"), "100");
    EXPECT_EQ(row.at("config.m"), "8");
    EXPECT_EQ(row.at("config.baselines"), "sap");
    EXPECT_EQ(row.at("config.bus.width"), "32");
    EXPECT_EQ(row.count("config.command_line"), 0u) << "it names the report's path, which differs between shards";
    EXPECT_EQ(row.at("frames_in_medians"), "3");
    EXPECT_EQ(row.at("median_total_ns"), "102");  // frames 1..3: 101, 102, 103
    EXPECT_EQ(row.at("median_pairs"), "12");
    EXPECT_EQ(row.at("sap_median_ns"), "302");
    EXPECT_NEAR(std::stod(row.at("sap_speedup")), 302.0 / 102.0, 1e-9);
    EXPECT_EQ(table.columns()[4], "objects");
    EXPECT_TRUE(is_timing_column(table.columns().back()));

    SweepTable again(grid);
    again.read_csv(table.csv(), "sweep.csv");
    EXPECT_EQ(again.csv(), table.csv()) << "a quoted reason and every column survive the round trip";
    EXPECT_EQ(again.rows().at(0).at("reason"), "m=8 needs \"48\" block RAMs, the device has 6");
}

TEST(SweepTable, BaselinesComeFromTheReportsSummaryAndItsWarmUpIsLeftOut) {
    const Grid grid(std::vector<Axis>{{"objects", {"50"}}});
    nlohmann::json with_summary = report(100, 300);
    with_summary["summary"] = {{"warmup_frames", 2}, {"too_few_frames", true},
                               {"baselines", {{"sap", {{"median_scaled_ns", 290.0}, {"p10_scaled_ns", 280.0},
                                                        {"p90_scaled_ns", 310.0}, {"speedup", 2.5}}}}}};
    const Row row = report_row(grid, grid.point(0), with_summary, 0.5).values;
    EXPECT_EQ(row.at("frames_in_medians"), "2");
    EXPECT_EQ(row.at("median_total_ns"), "102.5");  // frames 2 and 3: 102, 103
    EXPECT_EQ(row.at("too_few_frames"), "true");
    EXPECT_EQ(row.at("sap_median_ns"), "290");
    EXPECT_EQ(row.at("sap_p10_ns"), "280");
    EXPECT_EQ(row.at("sap_p90_ns"), "310");
    EXPECT_EQ(row.at("sap_speedup"), "2.5");
    EXPECT_TRUE(is_timing_column("sap_p90_ns"));
}

TEST(SweepTable, RefusesACsvOfAnotherGrid) {
    const Grid grid(std::vector<Axis>{{"objects", {"50"}}});
    SweepTable table(grid);
    EXPECT_THROW(table.read_csv("point,index,status,reason,m\n", "x.csv"), InputError);
    EXPECT_THROW(table.read_csv("point,index,status,reason,objects\np,zero,ok,,50\n", "x.csv"), InputError);
    EXPECT_THROW(table.read_csv("point,index,status,reason,objects\n\"p,0,ok,,50\n", "x.csv"), InputError);
}

TEST(SweepFigures, CrossoverIsInterpolatedInLogNOrMeasuredAtTheSmallestN) {
    const Grid grid(std::vector<Axis>{{"m", {"1", "8"}}, {"objects", {"100", "400"}}});
    SweepTable table(grid);
    // m=1 never wins; m=8 goes from 0.5x at 100 to 2x at 400: crossover at 100 * 4^(1/3).
    const double speedups[4] = {0.1, 0.2, 0.5, 2.0};
    for (std::size_t k = 0; k < 4; ++k) {
        PointRow row = failed_row(grid, grid.point(k), PointStatus::kOk, "", 0.5);
        row.values["status"] = "ok";
        row.values["config.board"] = "b";
        row.values["median_total_ns"] = "1000";
        row.values["sap_median_ns"] = std::to_string(1000 * speedups[k]);
        row.values["sap_speedup"] = std::to_string(speedups[k]);
        table.add(k, row);
    }
    const FigurePlan plan = plan_figures(grid, table);
    std::string crossover;
    for (const Figure& f : plan.figures) {
        if (f.file == "crossover.csv") crossover = f.data;
    }
    EXPECT_NE(crossover.find("b,1,sap,,none\n"), std::string::npos) << crossover;
    const std::size_t at = crossover.find("b,8,sap,");
    ASSERT_NE(at, std::string::npos) << crossover;
    EXPECT_NEAR(std::stod(crossover.substr(at + 8)), 100 * std::cbrt(4.0), 1e-6);
    EXPECT_NE(crossover.find("interpolated"), std::string::npos);
}

TEST(SweepFigures, PlotsAgainstNAreSkippedWithANoteWithoutAnObjectsAxis) {
    const Grid grid(std::vector<Axis>{{"m", {"1", "2"}}});
    SweepTable table(grid);
    PointRow row = report_row(grid, grid.point(0), report(100, 300), 0.1);
    table.add(0, row);
    const FigurePlan plan = plan_figures(grid, table);
    bool noted = false;
    for (const std::string& note : plan.notes) noted |= note.find("objects (or scene.objects) is not an axis") != std::string::npos;
    EXPECT_TRUE(noted);
    for (const Figure& f : plan.figures) EXPECT_EQ(f.file.rfind("time-", 0), std::string::npos) << f.file;
}

TEST(SweepNames, AxesAreFlagsOfRunOrSettingsAndAnUnknownOneNamesTheNearest) {
    const std::string help =
        "Usage: cdvp run (--trace FILE | --scene spheres [--objects N]) [options]\n"
        "  --objects N (0 to 4194304; 500)       spheres: number of spheres; see --frames\n"
        "  --m M (1 to 32; 8)                    parallelism\n"
        "  --report FILE                         JSON report\n"
        "  -q [ --quiet ]                        print nothing but errors\n";
    AxisNames known{help_options(help), false};
    EXPECT_EQ(known.names, (std::set<std::string>{"objects", "m"})) << "options the sweep sets are no axes";
    EXPECT_NO_THROW(check_axis_names({{"m", {"1"}}, {"objects", {"5"}}, {"bus.interrupt_ns", {"1"}}}, known))
        << "a dotted name passes while cdvp has no settings list";
    try {
        check_axis_names({{"objcts", {"5"}}}, known);
        ADD_FAILURE() << "objcts accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "--set objcts: no flag of cdvp run or setting has this name; the nearest is "
                                         "'objects' (see cdvp run --help)");
    }
    add_settings(R"([{"name": "bus.interrupt_ns", "flag": null}, {"name": "board.m", "flag": "--m"}])", known.names);
    known.settings_known = true;
    EXPECT_NO_THROW(check_axis_names({{"bus.interrupt_ns", {"1"}}, {"board.m", {"2"}}}, known));
    EXPECT_THROW(check_axis_names({{"bus.interupt_ns", {"1"}}}, known), InputError);
    EXPECT_EQ(nearest_name("bus.interupt_ns", known.names), "bus.interrupt_ns");
}

TEST(SweepFigures, AnotherVaryingAxisDrawsLinesOfItsOwnAndFitCsvGivesTheLargestMPerVariant) {
    const Grid grid(std::vector<Axis>{{"format", {"float32", "fixed16"}}, {"m", {"8", "24"}}, {"objects", {"100", "800"}}});
    SweepTable table(grid);
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const Point point = grid.point(k);
        PointRow row = failed_row(grid, point, PointStatus::kOk, "", 0.5);
        const Row& axes = row.values;
        const bool fixed = axes.at("format") == "fixed16";
        const bool large = axes.at("objects") == "800";
        row.values["status"] = "ok";
        row.values["config.board"] = "b";
        row.values["median_total_ns"] = std::to_string(1000 + k);
        // Narrower words fit more lanes; they add extra pairs.
        row.values["config.resources.largest_m"] = large ? (fixed ? "24" : "12") : "24";
        row.values["median_reference_pairs"] = "200";
        row.values["median_extra_pairs"] = fixed ? "50" : "0";
        table.add(k, row);
    }
    const FigurePlan plan = plan_figures(grid, table);
    std::string fit, time;
    bool frontier = false;
    for (const Figure& f : plan.figures) {
        if (f.file == "fit.csv") fit = f.data;
        if (f.file == "time-b.png") time = f.script;
        frontier |= f.file == "lanes-extra-b.png";
    }
    EXPECT_NE(time.find("'m=8 format=fixed16'"), std::string::npos) << time;
    EXPECT_NE(time.find("'m=24 format=float32'"), std::string::npos) << time;
    EXPECT_EQ(fit.substr(0, fit.find('\n')), "board,format,objects,largest_m,lanes,extra_pair_share,board_median_total_ns");
    // float32 at N=800: m=12 was not swept, so no time; fixed16 at N=800: m=24 ran (point 7).
    EXPECT_NE(fit.find("\nb,float32,800,12,23,0,\n"), std::string::npos) << fit;
    EXPECT_NE(fit.find("\nb,fixed16,800,24,47,0.25,1007\n"), std::string::npos) << fit;
    EXPECT_TRUE(frontier);
}

}  // namespace
}  // namespace cdvp
