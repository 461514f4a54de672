// What the figures say, planned without gnuplot: a style of its own for
// every series, titles that name the board, engine, frames and host factor,
// integer results drawn as steps on integer ticks, axes that fit the data,
// and no error axis below zero.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "sw/study/fidelity_figure.h"
#include "sw/study/figure_templates.h"
#include "sw/study/sweep_plots.h"
#include "sw/study/sweep_table.h"

namespace cdvp {
namespace {

// A table of ok rows over the grid, each filled in by 'fill' from its axes.
SweepTable table_of(const Grid& grid, const std::function<void(const Row& axes, Row& row)>& fill) {
    SweepTable table(grid);
    for (std::size_t k = 0; k < grid.size(); ++k) {
        PointRow row = failed_row(grid, grid.point(k), PointStatus::kOk, "", 0.5);
        const Row axes = row.values;
        row.values["status"] = "ok";
        row.values["config.board"] = "adm-xrc-ii";
        row.values["config.bus"] = "PCI 32-bit/33.3 MHz";
        row.values["config.fidelity"] = "fast";
        row.values["config.host"] = "pentium4-1.8";
        row.values["report_frames"] = "30";
        row.values["frames_in_medians"] = "28";
        fill(axes, row.values);
        table.add(k, row);
    }
    return table;
}

const Figure& figure_named(const FigurePlan& plan, const std::string& file) {
    for (const Figure& f : plan.figures) {
        if (f.file == file) return f;
    }
    ADD_FAILURE() << "no " << file;
    static const Figure none;
    return none;
}

double number_of(const Row& axes, const std::string& axis) { return std::stod(axes.at(axis)); }

// A board that wins from about 200 boxes, faster with m; sap on a calibrated host.
void timed(const Row& axes, Row& row) {
    const double n = number_of(axes, "objects"), m = axes.count("m") ? number_of(axes, "m") : 8;
    const double board = 50000 + n * n / (2 * m - 1), sap = 300 * n;
    row["mean_total_ns"] = std::to_string(board);
    row["sap_mean_host_ns"] = std::to_string(sap);
    row["sap_speedup"] = std::to_string(sap / board);
    row["sap_host_factor"] = "3.75";
    row["soa_mean_host_ns"] = std::to_string(sap / 2);
    row["soa_speedup"] = std::to_string(sap / 2 / board);
    row["soa_host_factor"] = "3.81";
    row["config.host_calibration.basis"] = "calibrated";
    row["config.host_calibration.profile_machine"] = "Xeon, 2026-01-01T00:00:00Z";
}

TEST(FigurePlan, EverySeriesOfAFigureHasAStyleOfItsOwnAndEachBaselineItsOwnToo) {
    const Grid grid(std::vector<Axis>{{"format", {"float32", "fixed16", "fixed8"}},
                                      {"m", {"1", "2", "4", "8", "16", "24", "32"}},
                                      {"objects", {"100", "400"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, timed));
    const Figure& time = figure_named(plan, "time-adm-xrc-ii.png");
    ASSERT_EQ(time.series.size(), 3u * 7u + 2u);
    std::set<SeriesStyle> styles;
    std::set<std::string> titles;
    std::vector<const PlotSeries*> software;
    for (const PlotSeries& s : time.series) {
        styles.insert(s.style);
        titles.insert(s.title);
        if (s.style.family == SeriesStyle::Family::kBaseline) software.push_back(&s);
    }
    EXPECT_EQ(styles.size(), time.series.size()) << "two series drawn alike";
    EXPECT_EQ(titles.size(), time.series.size()) << "two series named alike";
    ASSERT_EQ(software.size(), 2u);
    EXPECT_NE(software[0]->title.find("sap"), std::string::npos) << software[0]->title;
    EXPECT_NE(software[1]->title.find("soa"), std::string::npos) << software[1]->title;
    // One m keeps its colour and shape across formats; one format its dash.
    const auto style_of = [&](const std::string& title) {
        for (const PlotSeries& s : time.series) {
            if (s.title == title) return s.style;
        }
        ADD_FAILURE() << "no series " << title;
        return SeriesStyle{};
    };
    EXPECT_EQ(style_of("m=8 format=float32").colour, style_of("m=8 format=fixed16").colour);
    EXPECT_NE(style_of("m=8 format=float32").dash, style_of("m=8 format=fixed16").dash);
    EXPECT_EQ(style_of("m=8 format=fixed8").dash, style_of("m=24 format=fixed8").dash);
    EXPECT_NE(style_of("m=8 format=fixed8").colour, style_of("m=24 format=fixed8").colour);
    // The same series has the same style in the speedup figure.
    const Figure& speedup = figure_named(plan, "speedup-adm-xrc-ii-sap.png");
    for (const PlotSeries& s : speedup.series) EXPECT_EQ(s.style, style_of(s.title)) << s.title;
}

TEST(FigurePlan, ASpeedupOnADisturbedSoftwareTimingIsRingedAndACleanOneIsNot) {
    const Grid grid(std::vector<Axis>{{"m", {"1", "8"}}, {"objects", {"100", "200", "400"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, [](const Row& axes, Row& row) {
        timed(axes, row);
        const bool disturbed = axes.at("objects") == "200";
        row["sap_timing_quality"] = disturbed ? "disturbed" : "clean";
        row["soa_timing_quality"] = "clean";
    }));
    const Figure& sap = figure_named(plan, "speedup-adm-xrc-ii-sap.png");
    ASSERT_EQ(sap.series.size(), 3u) << "m=1, m=8 and the marks";
    const PlotSeries& marks = sap.series.back();
    EXPECT_EQ(marks.style.family, SeriesStyle::Family::kMark);
    ASSERT_EQ(marks.points.size(), 2u) << "N = 200 at m = 1 and m = 8";
    for (const SeriesPoint& p : marks.points) EXPECT_EQ(p.x, 200);
    // Each mark sits on a point of a line.
    for (const SeriesPoint& p : marks.points) {
        bool on_a_line = false;
        for (std::size_t k = 0; k + 1 < sap.series.size(); ++k) {
            for (const SeriesPoint& q : sap.series[k].points) on_a_line |= q.x == p.x && q.y == p.y;
        }
        EXPECT_TRUE(on_a_line) << p.x << ", " << p.y;
    }
    EXPECT_NE(figure_script(sap, "/tmp/s.png").find("n_marks = 1"), std::string::npos);
    const Figure& soa = figure_named(plan, "speedup-adm-xrc-ii-soa.png");
    for (const PlotSeries& s : soa.series) EXPECT_NE(s.style.family, SeriesStyle::Family::kMark) << "every soa timing was clean";
}

TEST(FigurePlan, StylesStayDistinctPastThePalettesLength) {
    std::set<SeriesStyle> styles;
    for (std::size_t m = 0; m < 36; ++m) {
        for (std::size_t v = 0; v < 10; ++v) styles.insert(series_style(m, 36, v, 10));
    }
    EXPECT_EQ(styles.size(), 360u);
    std::set<SeriesStyle> baselines;
    for (std::size_t b = 0; b < kBaselineStyles; ++b) baselines.insert(baseline_style(b));
    EXPECT_EQ(baselines.size(), kBaselineStyles);
    EXPECT_EQ(baselines.count(series_style(0, 1, 0, 1)), 0u) << "a baseline drawn like the board";
}

TEST(FigurePlan, TitlesSayTheBoardEngineFramesAndHostFactorAndWhatItRestsOn) {
    const Grid grid(std::vector<Axis>{{"m", {"8", "24"}}, {"objects", {"100", "400"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, timed));
    for (const char* file : {"time-adm-xrc-ii.png", "speedup-adm-xrc-ii-sap.png", "crossover-sap.png"}) {
        const std::string& title = figure_named(plan, file).title;
        for (const char* words : {"adm-xrc-ii (PCI 32-bit/33.3 MHz)", "fast engine", "30 frames a point",
                                  "means of the 28 after 2 warm-up", "pentium4-1.8", "native x 3.75 (sap)",
                                  "calibrated by the host profile of Xeon"}) {
            EXPECT_NE(title.find(words), std::string::npos) << file << " lacks '" << words << "':\n" << title;
        }
    }
    EXPECT_NE(figure_named(plan, "time-adm-xrc-ii.png").title.find("x 3.81 (soa)"), std::string::npos);
    // Without a profile the title says the factor is the preset's guess.
    const FigurePlan uncalibrated = plan_figures(grid, table_of(grid, [](const Row& axes, Row& row) {
        timed(axes, row);
        row["config.host_calibration.basis"] = "uncalibrated";
        row["sap_host_factor"] = row["soa_host_factor"] = "4";
    }));
    const std::string& title = figure_named(uncalibrated, "time-adm-xrc-ii.png").title;
    EXPECT_NE(title.find("native x 4 (sap, soa)"), std::string::npos) << title;
    EXPECT_NE(title.find("uncalibrated"), std::string::npos) << title;
}

TEST(FigurePlan, TheLargestMIsDrawnAsStepsOnIntegerTicksAndAgreeingVariantsShareALine) {
    const Grid grid(std::vector<Axis>{{"format", {"float32", "fixed32", "fixed16"}},
                                      {"objects", {"256", "1024", "4096"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, [](const Row& axes, Row& row) {
        const bool fixed16 = axes.at("format") == "fixed16";
        const double n = number_of(axes, "objects");
        row["config.m"] = "8";
        row["config.resources.largest_m"] = n == 256 ? (fixed16 ? "32" : "24") : (n == 1024 ? "12" : "11");
    }));
    const Figure& largest = figure_named(plan, "largest-m-adm-xrc-ii.png");
    EXPECT_EQ(largest.template_name, "largest_m");
    EXPECT_NE(figure_template("largest_m").find("with fsteps"), std::string::npos) << "steps, not slopes";
    ASSERT_EQ(largest.series.size(), 2u);
    EXPECT_EQ(largest.series[0].title, "format=float32, fixed32");
    EXPECT_EQ(largest.series[1].title, "format=fixed16");
    EXPECT_EQ(largest.y.min, 0);
    ASSERT_FALSE(largest.y.ticks.empty());
    for (const auto& [value, label] : largest.y.ticks) {
        EXPECT_EQ(value, std::floor(value)) << "a tick between integers: " << label;
        EXPECT_EQ(label, std::to_string(static_cast<int>(value)));
    }
    EXPECT_GE(largest.y.max, 32);
    // N ticked at the values swept, not between them.
    std::vector<double> n_ticks;
    for (const auto& tick : largest.x.ticks) n_ticks.push_back(tick.first);
    EXPECT_EQ(n_ticks, (std::vector<double>{256, 1024, 4096}));
    EXPECT_TRUE(largest.x.log);
}

TEST(FigurePlan, OneMGetsACrossoverAxisOneStepEitherSideAndALabelledPoint) {
    const Grid grid(std::vector<Axis>{{"objects", {"100", "200", "400", "800"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, [](const Row& axes, Row& row) {
        timed(axes, row);
        row["config.m"] = "24";
    }));
    const Figure& crossover = figure_named(plan, "crossover-sap.png");
    EXPECT_FALSE(crossover.x.log);
    EXPECT_EQ(crossover.x.min, 23);
    EXPECT_EQ(crossover.x.max, 25);
    ASSERT_EQ(crossover.x.ticks.size(), 1u);
    EXPECT_EQ(crossover.x.ticks[0].second, "24");
    ASSERT_EQ(crossover.series.size(), 1u);
    ASSERT_EQ(crossover.series[0].points.size(), 1u);
    const SeriesPoint& point = crossover.series[0].points[0];
    EXPECT_GT(point.y, 100);
    EXPECT_LT(point.y, 800);
    EXPECT_EQ(point.label, short_number(point.y));
    EXPECT_LT(crossover.y.min, point.y);
    EXPECT_GT(crossover.y.max, point.y);
}

TEST(FigurePlan, PhasesAreSharesOfTheFrameAndEveryBarNamesItsPoint) {
    const Grid grid(std::vector<Axis>{{"format", {"float32", "fixed16"}}, {"m", {"1", "24"}}, {"objects", {"50", "2000"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, [](const Row& axes, Row& row) {
        const double n = number_of(axes, "objects");
        row["mean_upload_ns"] = std::to_string(30 * n);
        row["mean_compute_ns"] = std::to_string(n * n / number_of(axes, "m"));
        row["mean_readback_ns"] = "20000";
        row["mean_total_ns"] = std::to_string(30 * n + n * n / number_of(axes, "m") + 20000);
    }));
    const Figure& phases = figure_named(plan, "phases-adm-xrc-ii.png");
    ASSERT_EQ(phases.x.ticks.size(), 8u);
    EXPECT_EQ(phases.x.ticks[0].second, "N=50 m=1 format=float32: 24 us");
    EXPECT_EQ(phases.x.ticks[7].second, "N=2000 m=24 format=fixed16: 247 us");
    EXPECT_EQ(phases.y.max, 100);
    ASSERT_EQ(phases.series.size(), 6u);
    for (std::size_t bar = 0; bar < 8; ++bar) {
        EXPECT_NEAR(phases.series.back().points[bar].y, 100, 1e-9) << "the shares of bar " << bar;
        for (const PlotSeries& s : phases.series) EXPECT_GE(s.points[bar].y, s.points[bar].base);
    }
}

TEST(FigurePlan, TheFidelityAxesAreLogExactLevelsSitOnTheFloorAndLabelsOfCoincidingLevelsStayApart) {
    const std::vector<FidelityPoint> levels{{"cycle, quantum 0", 3.38, 0}, {"fast, quantum 0", 0.140, 0},
                                            {"fast, quantum 100 ns", 0.142, 0}, {"fast, quantum 1 us", 0.141, 0},
                                            {"fast, quantum 10 us", 0.153, 0}, {"fast, quantum 100 us", 0.147, 0},
                                            {"analytic, formula bus", 0.02, 0.35}, {"analytic", 0.021, 2e-9}};
    const Figure figure = fidelity_figure(levels, "adm-xrc-ii, spheres objects=500, m=24, 30 frames");
    EXPECT_TRUE(figure.x.log);
    EXPECT_TRUE(figure.y.log);
    ASSERT_FALSE(figure.x.ticks.empty());
    EXPECT_EQ(figure.x.ticks.front().second, "0") << "the floor stands for exact";
    const double floor = figure.x.ticks.front().first;
    EXPECT_GT(floor, figure.x.min);
    EXPECT_LT(floor, 0.35 / 5) << "a decade below the least error";
    EXPECT_GT(figure.x.max, 0.35);
    EXPECT_EQ(figure.series[0].points[0].x, floor);
    EXPECT_EQ(figure.series[7].points[0].x, floor) << "below a millionth of a percent is summing order: exact";
    EXPECT_EQ(figure.series[6].points[0].x, 0.35);
    EXPECT_NE(figure.series[0].points[0].label.find("exact"), std::string::npos);
    EXPECT_NE(figure.series[6].points[0].label.find("error 0.35 %"), std::string::npos) << figure.series[6].points[0].label;
    ASSERT_EQ(figure.series.size(), levels.size()) << "one series per level";
    std::set<SeriesStyle> styles;
    std::vector<double> label_logs;
    for (const PlotSeries& s : figure.series) {
        styles.insert(s.style);
        ASSERT_EQ(s.points.size(), 1u);
        EXPECT_GE(s.points[0].x, figure.x.min);
        // The exact levels share one error: their labels must not share a line.
        if (s.points[0].x == floor) label_logs.push_back(std::log10(s.points[0].label_y));
        EXPECT_GE(s.points[0].label_y, figure.y.min);
        EXPECT_LE(s.points[0].label_y, figure.y.max);
    }
    EXPECT_EQ(styles.size(), levels.size());
    std::sort(label_logs.begin(), label_logs.end());
    ASSERT_EQ(label_logs.size(), 7u);
    for (std::size_t k = 1; k < label_logs.size(); ++k) {
        EXPECT_GT(label_logs[k] - label_logs[k - 1], 0.03) << "two labels on one line";
    }
    EXPECT_NE(figure.title.find("m=24, 30 frames"), std::string::npos);
}

TEST(FigurePlan, ExtraPairsGetALogAxisWithARowForZeroAndNothingBelowIt) {
    const Grid grid(std::vector<Axis>{{"format", {"float32", "fixed16", "fixed8"}}, {"objects", {"256", "65536"}}});
    const FigurePlan plan = plan_figures(grid, table_of(grid, [](const Row& axes, Row& row) {
        const std::string& format = axes.at("format");
        row["config.resources.largest_m"] = format == "float32" ? "11" : "32";
        row["median_reference_pairs"] = "10000";
        row["median_extra_pairs"] = format == "float32" ? "0" : (format == "fixed16" ? "2" : "17000");
    }));
    const Figure& frontier = figure_named(plan, "lanes-extra-adm-xrc-ii.png");
    EXPECT_TRUE(frontier.y2.log);
    EXPECT_GT(frontier.y2.min, 0);
    ASSERT_FALSE(frontier.y2.ticks.empty());
    EXPECT_EQ(frontier.y2.ticks.front().second, "0");
    EXPECT_LT(frontier.y2.ticks.front().first, 0.02) << "zero's row under 0.02 %, the smallest share";
    EXPECT_GE(frontier.y2.max, 170);
    EXPECT_EQ(frontier.y.min, 0);
    for (const auto& [value, label] : frontier.y.ticks) EXPECT_EQ(value, std::floor(value)) << label;
}

TEST(FigurePlan, TheTemplatesPalettesAreAsLongAsThePlanAssumes) {
    const std::string& common = figure_template("common");
    const auto size_of = [&](const std::string& array) {
        std::smatch match;
        const std::regex declared("array " + array + "\\[([0-9]+)\\]");
        return std::regex_search(common, match, declared) ? std::stoul(match[1]) : 0ul;
    };
    EXPECT_EQ(size_of("palette"), kColours);
    EXPECT_EQ(size_of("shape_filled"), kShapes);
    EXPECT_EQ(size_of("shape_open"), kShapes);
    EXPECT_EQ(size_of("dash_type"), kDashes);
    EXPECT_EQ(size_of("baseline_colour"), kBaselineStyles);
    EXPECT_EQ(common.find("#F0E442"), std::string::npos) << "Okabe and Ito's yellow is unreadable on white";
    EXPECT_THROW(figure_template("no-such-figure"), std::logic_error);
}

TEST(FigurePlan, TheScriptFillsTheTemplateWithTheFiguresValues) {
    Figure figure;
    figure.file = "f.png";
    figure.template_name = "time";
    figure.title = "first line\nsecond \"quoted\"";
    figure.x.label = "N";
    figure.x.log = true;
    figure.x.min = 40;
    figure.x.ticks = {{50, "50"}, {100, "100"}};
    PlotSeries s;
    s.title = "m=8";
    s.points = {{50, 1.5, "a label"}, {100, 2.5}};
    figure.series = {s, s};
    figure.series[1].style = baseline_style(1);
    const std::string script = figure_script(figure, "/tmp/out.png");
    for (const char* expected : {"output_path = \"/tmp/out.png\"", "title_text = \"first line\\nsecond \\\"quoted\\\"\"",
                                 "title_lines = 2", "x_log = 1", "x_min = 40", "x_ticks = \"(\\\"50\\\" 50, \\\"100\\\" 100)\"",
                                 "n_series = 2", "array series_family[2] = [1, 2]", "array series_colour[2] = [1, 2]",
                                 "50 1.5 \"a label\" 50 1.5 0\n", "\n\n\n50 1.5 \"a label\"", "y_log = 0"}) {
        EXPECT_NE(script.find(expected), std::string::npos) << "lacks " << expected << " in\n" << script;
    }
    const std::string values = script.substr(0, script.find("$series << EOD"));
    EXPECT_EQ(values.find("x_max"), std::string::npos) << "an axis end left to gnuplot is not set";
    EXPECT_LT(script.find("$series << EOD"), script.find(figure_template("common")));
    EXPECT_LT(script.find(figure_template("common")), script.find(figure_template("time")));
}

}  // namespace
}  // namespace cdvp
