// What the figures of `cdvp sweep` share: the ok rows placed on the figures'
// axes (board, N, m and the other axes that vary), their series, and the
// text of gnuplot data blocks.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sw/cli/sweep_grid.h"
#include "sw/cli/sweep_plots.h"
#include "sw/cli/sweep_table.h"

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
    RowView row;
};

// One line of a figure: the points (x, y) sorted by x, titled by m and variant.
struct Line {
    double m = 0;
    std::string variant;
    std::vector<std::pair<double, double>> points;
    std::string title() const;
};
// Lines in grid order: by variant, then m.
using Series = std::map<std::pair<std::string, double>, Line>;

// For the samples of `board`: y = column x scale against N, one line per (variant, m).
Series series(const std::vector<Sample>& samples, const std::string& board, const std::string& column, double scale);

double number(const RowView& row, const std::string& column);  // NaN when absent
std::string text(const RowView& row, const std::string& column);
std::string quoted(const std::string& s);  // single-quoted for gnuplot
std::string file_part(std::string s);      // file-name safe, as point ids are
std::string num(double v);
// "$NAME << EOD", lines of x y, "EOD".
std::string datablock(const std::string& name, const std::vector<std::pair<double, double>>& points);

// What fits the device: fit.csv (per board, variant and N, the largest m
// from the reports' config.resources.largest_m, its lanes, the board's time
// there when the sweep ran that m, and the extra pairs a number format adds),
// largest m against N, and lanes against extra pairs when a variant varies.
void add_fit_figures(const std::vector<Sample>& samples, const std::vector<std::string>& boards,
                     const std::vector<std::string>& variant_axes, FigurePlan& plan);

}  // namespace cdvp::sweep_figures
