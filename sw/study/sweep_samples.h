// What the figures of `cdvp sweep` share: the ok rows placed on the figures'
// axes (board, N, m and the other axes that vary), their series and styles,
// and the words their titles take from the rows (engine, frames, host).
#pragma once

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sw/study/figure_plan.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_plots.h"
#include "sw/study/sweep_table.h"

namespace cdvp::sweep_figures {

// A point that ran, placed on the figures' axes. Its variant is the values of
// every axis other than board, N and m that takes more than one value
// ("format=fixed16"), so each variant gets lines of its own.
struct Sample {
    std::string board;
    double m = 0;
    double n = 0;
    std::string variant;                      // empty when no other axis varies
    std::vector<std::string> variant_values;  // the same values, one per varying axis
    std::string variant_order;  // the variant's values' places in their axes, for grid order
    std::size_t variant_place = 0;  // its place among the sweep's variants
    std::size_t m_place = 0;        // m's place among the sweep's values of m
    // The scene or trace the point ran (the axis's value, else the row's
    // source's first word; empty when the row names none); the board's
    // algorithm and number format (from the axes, else the row's settings;
    // empty when neither says); and the variant's other axes ("clock_mhz=250").
    std::string scene, algorithm, format, setup;
    RowView row;
};

// The samples, with the counts their places are out of.
struct Samples {
    std::vector<Sample> all;
    std::vector<std::string> boards;  // in the order first met
    std::size_t variants = 1, ms = 1;
};

// One line of a figure: the points (x, y) sorted by x, of one m and variant.
struct Line {
    double m = 0;
    std::string variant;
    std::size_t m_place = 0, variant_place = 0;
    std::vector<std::pair<double, double>> points;
    std::string title() const;  // "m=8 format=fixed16"
};
// Lines in grid order: by variant, then m.
using Series = std::map<std::pair<std::string, double>, Line>;

// For the samples of `board`: y = column x scale against N, one line per (variant, m).
Series series(const Samples& samples, const std::string& board, const std::string& column, double scale);
// The lines as board series: one colour and point shape per m, one dash and
// fill per variant (or the other way about when variants outnumber the m),
// the same in every figure of the sweep.
std::vector<PlotSeries> board_series(const Series& lines, const Samples& samples);

// The smallest N at which a ratio (a speedup, an energy ratio) reaches 1,
// and how it was found: interpolated in log N between the measured N around
// it (the ratio itself, or with 'log_ratio' its logarithm: a power law
// between the two, the straight line a log-log figure draws), measured (the
// smallest N already reaches it: the crossover is at or below it), or none.
struct Crossover {
    double n = 0;
    const char* how = "none";
    std::vector<double> rests_on;  // the N whose ratios it was taken from
};
// The first N at which the ratio reaches 1; `ratios` as (N, ratio), sorted by N.
Crossover crossover(const std::vector<std::pair<double, double>>& ratios, bool log_ratio = false);
// The smallest N from which the ratio stays at 1 or above through the largest
// N: the crossover after the last N below 1 (none when that is the largest),
// interpolated in log ratio, so that it sits where the lines of a log-log
// figure of the two times cross.
Crossover lasting_crossover(const std::vector<std::pair<double, double>>& ratios);

// A frame's time with a unit a reader takes in at once: "83.1 us", "2.27 ms", "1.61 s".
std::string frame_time_words(double ns);

// The extremes of every y over the series.
std::pair<double, double> y_extent(const std::vector<PlotSeries>& all);
// N on a log axis that just holds the points, ticked at the swept values.
PlotAxis n_axis(const std::vector<const Sample*>& points);
// A log y axis over the series (and `include`, unless NaN), padded, with ticks a reader can read off.
PlotAxis log_y_axis(const std::string& label, const std::vector<PlotSeries>& all, double include = NAN);

double number(const RowView& row, const std::string& column);  // NaN when absent
std::string text(const RowView& row, const std::string& column);
std::string file_part(std::string s);  // file-name safe, as point ids are
std::string num(double v);
std::vector<const Sample*> on_board(const Samples& samples, const std::string& board);

// Title lines from the rows (sweep_context.cpp):
// "adm-xrc-ii (PCI 32-bit/33.3 MHz)"
std::string board_words(const std::vector<const Sample*>& points);
// "board simulated on the fast engine; 30 frames a point, means of the 28 after 2 warm-up"
std::string run_words(const std::vector<const Sample*>& points);
// Two lines: "software on the modelled host pentium4-1.8: native x 3.75 (sap), x 3.81 (soa)"
// and what the factors rest on: "factors calibrated by the host profile of ...".
std::string software_words(const std::vector<const Sample*>& points, const std::vector<std::string>& baselines);
// "sap (Bullet's sweep and prune)"
std::string baseline_words(const std::string& baseline);

// What fits the device: fit.csv (per board, variant and N, the largest m
// from the reports' config.resources.largest_m, its lanes, the board's time
// there when the sweep ran that m, and the extra pairs a number format adds),
// largest m against N, and lanes against extra pairs when a variant varies.
void add_fit_figures(const Samples& samples, const std::vector<std::string>& variant_axes, FigurePlan& plan);
// Each board's phases as stacked shares of its mean frame, a bar per point.
void add_phase_figures(const Samples& samples, FigurePlan& plan);
// crossover.csv and, per baseline the board beats, crossover N against m.
void add_crossovers(const Samples& samples, const std::vector<std::string>& variant_axes,
                    const std::vector<std::string>& baselines, FigurePlan& plan);
// The sweep's answer (sw/study/sweep_answer.h): answer.csv, answer.md, the
// figures of time and energy against N, and the short form for the terminal.
void add_answer(const Samples& samples, const std::vector<std::string>& baselines, FigurePlan& plan);

}  // namespace cdvp::sweep_figures
