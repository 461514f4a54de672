// The sweep's answer from rows made by hand: at each N the fastest
// configuration held to the fastest software, what bounds it, the crossovers
// on time and on energy (the band's ends too) and what they rest on, the
// files' text and the figures' series.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "sw/study/sweep_answer.h"
#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_plots.h"

// Its own namespace: the test files of a binary are compiled together.
namespace cdvp::answer_test {
namespace {

using sweep_figures::Crossover;

// A board whose m = 2 wins at 100 boxes and m = 8 above; sap the fastest
// software up to 400 boxes, dbvt above; dbvt's timing disturbed at 1600,
// and m = 8's clock not met at 400. Host 10 W (asleep at 2.5 W on the
// board), the board's own parts 3 W.
const double kSizes[] = {100, 400, 1600};
double board_ns(double n, double m) { return (m == 2 ? 40000 : 80000) + n * n / (2 * m - 1); }
double sap_ns(double n) { return 300 * n; }
double dbvt_ns(double n) { return 100000 + 100 * n; }

// A value as sweep.csv holds it, to 10 significant digits.
std::string exact(double v) { return number_text(v); }

// The rows; without 'software', as a sweep without --baseline has them.
SweepTable answer_table(const Grid& grid, bool software = true) {
    SweepTable table(grid);
    for (std::size_t k = 0; k < grid.size(); ++k) {
        PointRow row = failed_row(grid, grid.point(k), PointStatus::kOk, "", 0.5);
        Row& r = row.values;
        const double n = std::stod(r.at("objects")), m = std::stod(r.at("m"));
        const double board = board_ns(n, m), upload = 30000, compute = board - upload - 1000;
        r["status"] = "ok";
        r["config.board"] = "alveo-u250";
        r["config.source"] = "spheres objects=" + r.at("objects") + " seed=1";
        r["config.format"] = "float32";
        r["config.settings.board.algorithm.value"] = "all_pairs";
        r["config.clock_mhz"] = "300";
        r["config.resources.timing.fmax_mhz"] = "350";
        r["config.resources.timing.meets_clock"] = m == 8 && n == 400 ? "false" : "true";
        r["mean_total_ns"] = exact(board);
        r["mean_upload_ns"] = exact(upload);
        r["mean_compute_ns"] = exact(compute);
        r["mean_driver_ns"] = "1000";
        r["median_load_wait_slots"] = "0";
        const double host_j = 2.5 * board * 1e-9, own_j = 3 * board * 1e-9;
        r["mean_energy_j"] = exact(host_j + own_j);
        r["mean_energy_host_j"] = exact(host_j);
        for (const auto& [name, ns] : {std::pair{"sap", sap_ns(n)}, std::pair{"dbvt", dbvt_ns(n)}}) {
            if (!software) break;
            const std::string b = name;
            r[b + "_mean_host_ns"] = exact(ns);
            r[b + "_speedup"] = exact(ns / board);
            r[b + "_energy_j"] = exact(10 * ns * 1e-9);
            r[b + "_energy_ratio"] = exact(10 * ns * 1e-9 / (host_j + own_j));
            r[b + "_timing_quality"] = b == "dbvt" && n == 1600 ? "disturbed" : "clean";
        }
        table.add(k, row);
    }
    return table;
}

const Grid kGrid(std::vector<Axis>{{"m", {"2", "8"}}, {"objects", {"100", "400", "1600"}}});

// The N where a ratio, a power of N between n0 and n1, reaches 1.
double log_crossing(double n0, double r0, double n1, double r1) {
    return n0 * std::pow(n1 / n0, std::log(r0) / (std::log(r0) - std::log(r1)));
}

const Figure& planned_file(const FigurePlan& plan, const std::string& file) {
    for (const Figure& f : plan.figures) {
        if (f.file == file) return f;
    }
    ADD_FAILURE() << "no " << file;
    static const Figure none;
    return none;
}

std::vector<std::vector<std::string>> answer_rows(const FigurePlan& plan) {
    return parse_csv(planned_file(plan, "answer.csv").data, "answer.csv");
}

TEST(SweepAnswer, TheFastestConfigurationAtEachNHeldToTheFastestSoftwareOnItsRow) {
    const FigurePlan plan = plan_figures(kGrid, answer_table(kGrid));
    const auto rows = answer_rows(plan);
    ASSERT_EQ(rows.size(), 4u);
    const std::vector<std::string>& header = rows[0];
    auto at = [&](std::size_t row, const std::string& column) {
        const auto place = std::find(header.begin(), header.end(), column);
        EXPECT_NE(place, header.end()) << column;
        return place == header.end() ? std::string() : rows[row][place - header.begin()];
    };
    const std::string best_m[] = {"2", "8", "8"}, software[] = {"sap", "sap", "dbvt"};
    for (std::size_t k = 0; k < 3; ++k) {
        const double n = kSizes[k], m = std::stod(best_m[k]);
        const double sw = software[k] == "sap" ? sap_ns(n) : dbvt_ns(n);
        EXPECT_EQ(at(k + 1, "scene"), "spheres");
        EXPECT_EQ(std::stod(at(k + 1, "objects")), n);
        EXPECT_EQ(at(k + 1, "m"), best_m[k]) << n;
        EXPECT_EQ(at(k + 1, "configuration"), "alveo-u250 all_pairs m=" + best_m[k] + " float32");
        EXPECT_EQ(at(k + 1, "software"), software[k]) << n;
        EXPECT_NEAR(std::stod(at(k + 1, "speedup")), sw / board_ns(n, m), 1e-6);
        EXPECT_NEAR(std::stod(at(k + 1, "board_frame_ns")), board_ns(n, m), 1e-3);
    }
    EXPECT_EQ(at(1, "bound_by"), "bus") << "30 us of upload in a 43 us frame";
    EXPECT_EQ(at(3, "bound_by"), "compute");
    EXPECT_EQ(at(3, "software_timing"), "disturbed");
    EXPECT_EQ(at(2, "clock_met"), "no");
    // Ahead from between 100 (m = 2 behind sap) and 400 on, through 1600.
    const double expected = log_crossing(100, sap_ns(100) / board_ns(100, 2), 400, sap_ns(400) / board_ns(400, 8));
    EXPECT_NEAR(std::stod(at(1, "time_crossover_n")), expected, 1e-6 * expected);
    EXPECT_EQ(at(1, "time_crossover_how"), "interpolated");
    EXPECT_EQ(at(1, "time_crossover_timing"), "clean") << "it rests on 100 and 400, not on 1600's disturbed timing";
    EXPECT_EQ(at(1, "time_crossover_clock"), "no") << "m = 8 at 400 is beyond its clock";
    EXPECT_EQ(at(3, "time_crossover_n"), at(1, "time_crossover_n")) << "a scene's crossovers on each of its rows";
}

TEST(SweepAnswer, TheEnergyBandTakesTheBoardsOwnPowerAndTheHostsAtOppositeEnds) {
    const FigurePlan plan = plan_figures(kGrid, answer_table(kGrid));
    const auto rows = answer_rows(plan);
    const auto& header = rows[0];
    auto column = [&](const std::string& name) { return std::find(header.begin(), header.end(), name) - header.begin(); };
    // At 400: m = 8, sap: software 10 W x 120 us against the board's 5.5 W x 90.7 us.
    const double board = board_ns(400, 8), sw_j = 10 * sap_ns(400) * 1e-9, own = 3 * board * 1e-9, host = 2.5 * board * 1e-9;
    EXPECT_NEAR(std::stod(rows[2][column("energy_ratio")]), sw_j / (own + host), 1e-6);
    EXPECT_NEAR(std::stod(rows[2][column("energy_ratio_low")]), 0.7 * sw_j / (2 * own + 0.7 * host), 1e-6);
    EXPECT_NEAR(std::stod(rows[2][column("energy_ratio_high")]), 2 * sw_j / (0.5 * own + 2 * host), 1e-6);
    // The band's crossovers bracket the model's.
    const double early = std::stod(rows[1][column("energy_crossover_early_n")]);
    const double model = std::stod(rows[1][column("energy_crossover_n")]);
    EXPECT_LE(early, model);
    const std::string late = rows[1][column("energy_crossover_late_n")];
    if (!late.empty()) {
        EXPECT_GE(std::stod(late), model);
    }
}

TEST(SweepAnswer, ACrossoverIsWhereTheBoardStaysAheadThroughTheLargestN) {
    using sweep_figures::lasting_crossover;
    const Crossover behind_again = lasting_crossover({{100, 0.5}, {400, 1.5}, {1600, 0.8}});
    EXPECT_EQ(behind_again.n, 0) << "ahead at 400 only: no N from which it stays ahead";
    EXPECT_STREQ(behind_again.how, "none");
    const Crossover after_a_dip = lasting_crossover({{100, 1.2}, {400, 0.9}, {1600, 1.1}});
    EXPECT_NEAR(after_a_dip.n, log_crossing(400, 0.9, 1600, 1.1), 1e-9);
    EXPECT_EQ(after_a_dip.rests_on, (std::vector<double>{400, 1600}));
    const Crossover always = lasting_crossover({{100, 1.0}, {400, 3}});
    EXPECT_EQ(always.n, 100);
    EXPECT_STREQ(always.how, "measured");
}

TEST(SweepAnswer, ItsFiguresDrawEachWinningConfigurationOnceTheSoftwareAndTheCrossover) {
    const FigurePlan plan = plan_figures(kGrid, answer_table(kGrid));
    for (const std::string file : {"answer-time.png", "answer-energy.png"}) {
        const Figure& figure = planned_file(plan, file);
        EXPECT_EQ(figure.template_name, "answer");
        ASSERT_EQ(figure.series.size(), 4u) << file << ": m = 2, m = 8, the software, the crossover";
        std::set<std::string> titles;
        for (const PlotSeries& s : figure.series) titles.insert(s.title);
        EXPECT_EQ(titles.size(), 4u) << "a legend without duplicates";
        EXPECT_EQ(figure.series[0].title, "alveo-u250 all_pairs m=2 float32 (fastest board at N = 100)");
        EXPECT_EQ(figure.series[0].points.size(), 3u) << "the configuration's whole line, not only where it wins";
        EXPECT_EQ(figure.series[2].style.family, SeriesStyle::Family::kBaseline);
        EXPECT_EQ(figure.series[2].title, "fastest software at each N: sap, dbvt");
        const PlotSeries& mark = figure.series[3];
        EXPECT_EQ(mark.style.family, SeriesStyle::Family::kMark);
        ASSERT_EQ(mark.points.size(), 2u);
        EXPECT_EQ(mark.points[0].x, mark.points[1].x) << "a vertical line";
        EXPECT_EQ(mark.points[0].y, figure.y.min);
        EXPECT_EQ(mark.points[1].y, figure.y.max);
    }
    const Figure& time = planned_file(plan, "answer-time.png");
    EXPECT_NE(time.series[3].title.find("board faster from N ~ "), std::string::npos) << time.series[3].title;
    EXPECT_EQ(time.y.label, "time a frame (us)");
    // Each title line fits the figure's width at about 7 pixels a character.
    std::size_t longest = 0, start = 0;
    for (std::size_t end = time.title.find('\n'); start != std::string::npos;
         start = end == std::string::npos ? end : end + 1, end = time.title.find('\n', start)) {
        longest = std::max(longest, (end == std::string::npos ? time.title.size() : end) - start);
    }
    EXPECT_LT(longest * 7, static_cast<std::size_t>(time.width)) << time.title;
}

TEST(SweepAnswer, NoEnergyFigureWithoutEnergyOnALogAxisThatCannotHoldZero) {
    SweepTable table = answer_table(kGrid);
    table.for_each([&](std::size_t index, const RowView&) {
        PointRow row = table.point_row(index);
        row.values["mean_energy_j"] = "0";  // no --board: no power figures
        table.add(index, row);
    });
    const FigurePlan plan = plan_figures(kGrid, table);
    EXPECT_EQ(planned_file(plan, "answer-time.png").template_name, "answer");
    for (const Figure& f : plan.figures) EXPECT_NE(f.file, "answer-energy.png") << "a figure gnuplot would refuse";
    EXPECT_EQ(answer_rows(plan).size(), 4u) << "the answer is written all the same";
}

TEST(SweepAnswer, WithoutSoftwareItNamesTheFastestBoardAndSaysThereIsNothingToHoldItTo) {
    const FigurePlan plan = plan_figures(kGrid, answer_table(kGrid, false));
    const auto rows = answer_rows(plan);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[3][2], "alveo-u250 all_pairs m=8 float32");
    EXPECT_EQ(rows[3][10], "") << "no software";
    EXPECT_NE(planned_file(plan, "answer.md").data.find("No software was timed (no --baseline)"), std::string::npos);
    const Figure& time = planned_file(plan, "answer-time.png");
    EXPECT_EQ(time.series.size(), 2u) << "the two configurations, no software and no crossover";
    EXPECT_NE(time.title.find("no software timed (no --baseline)"), std::string::npos) << time.title;
    EXPECT_EQ(time.title.find("software on the modelled host"), std::string::npos) << time.title;
}

TEST(SweepAnswer, ItsShortFormHasALineAnNAndOneForTheCrossovers) {
    const FigurePlan plan = plan_figures(kGrid, answer_table(kGrid));
    std::vector<std::string> lines;
    for (std::size_t start = 0, end; (end = plan.answer.find('\n', start)) != std::string::npos; start = end + 1) {
        lines.push_back(plan.answer.substr(start, end - start));
    }
    ASSERT_EQ(lines.size(), 5u) << plan.answer;
    EXPECT_EQ(lines[0].rfind("  scene ", 0), 0u) << lines[0];
    EXPECT_NE(lines[2].find("alveo-u250 all_pairs m=8 float32"), std::string::npos) << lines[2];
    EXPECT_EQ(lines[4].rfind("  spheres: faster from N ~ ", 0), 0u) << lines[4];
    const std::string md = planned_file(plan, "answer.md").data;
    EXPECT_NE(md.find("| 400 | alveo-u250 all_pairs m=8 float32 |"), std::string::npos) << md;
    EXPECT_NE(md.find("The software's timing was disturbed at N = 1600"), std::string::npos) << md;
    EXPECT_NE(md.find("At N = 400 the fastest configuration's clock is beyond what its design reaches"), std::string::npos)
        << md;
}

}  // namespace
}  // namespace cdvp::answer_test
