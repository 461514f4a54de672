// A figure as a plan: what it shows (series, axes, title, labels), chosen in
// C++ from the data, and drawn by a gnuplot template (sw/study/figures/NAME.gp)
// that the plan fills with variables and data blocks. The plan holds no
// gnuplot commands, so what a figure says can be tested without gnuplot, and
// how it looks is changed in the templates.
#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cdvp {

// How a series is drawn, as places in the palettes of figures/common.gp:
// board (simulated) series take a colour and a point shape from one palette,
// software baselines black or grey with their own dashes and shapes, so no
// baseline looks like another or like the board.
struct SeriesStyle {
    // kMark: points drawn over the lines without a line of their own (the
    // points whose software timing was disturbed), after every other series.
    enum class Family { kBoard = 1, kBaseline = 2, kMark = 3 };
    Family family = Family::kBoard;
    std::size_t colour = 0;  // kColours of them for the board, kBaselineStyles for baselines
    std::size_t shape = 0;   // kShapes point shapes, each open or filled
    std::size_t dash = 0;    // kDashes dash patterns
    bool filled = true;
    bool operator<(const SeriesStyle& o) const;
    bool operator==(const SeriesStyle& o) const { return !(*this < o) && !(o < *this); }
};
// The sizes of common.gp's arrays (a test holds the template to them).
constexpr std::size_t kColours = 6, kShapes = 6, kDashes = 5, kBaselineStyles = 4;

// The style of a series placed on two dimensions of a figure (m and a variant,
// say): the dimension with more values takes the colour and point shape, the
// other the dash pattern and the points' fill, so the lines of one m share a
// colour and those of one variant a dash. Distinct for up to 36 x 10 places.
SeriesStyle series_style(std::size_t first, std::size_t first_count, std::size_t second, std::size_t second_count);
// The k-th software baseline's style.
SeriesStyle baseline_style(std::size_t k);
// The style of a mark series (Family::kMark).
SeriesStyle mark_style();

struct SeriesPoint {
    SeriesPoint() = default;
    SeriesPoint(double x_, double y_, std::string label_ = {}) : x(x_), y(y_), label(std::move(label_)) {}
    double x = 0, y = 0;
    std::string label;  // drawn beside the point; empty for none
    // Where the label goes when not beside the point (a leader joins them).
    double label_x = std::nan(""), label_y = std::nan("");
    double base = 0;    // where a bar starts (stacked bars)
};

struct PlotSeries {
    std::string title;  // the legend's words
    SeriesStyle style;
    std::vector<SeriesPoint> points;
    bool second_axis = false;  // on the figure's second y axis (or panel)
    // How many later series are drawn over it along some stretch: it is
    // drawn that much wider, so it shows beneath them.
    std::size_t beneath = 0;
};

struct PlotAxis {
    std::string label;
    bool log = false;
    double min = std::nan(""), max = std::nan("");  // NaN: gnuplot's autoscale
    // Ticks at these values, each with its text; empty: gnuplot's own.
    std::vector<std::pair<double, std::string>> ticks;
};

struct Figure {
    std::string file;            // "time-adm-xrc-ii.png", "crossover.csv", ...
    std::string template_name;   // figures/NAME.gp draws it; empty for a data file
    std::string title;           // lines joined by '\n'
    PlotAxis x, y, y2;
    std::vector<PlotSeries> series;
    std::map<std::string, double> numbers;  // what one template needs besides (reference_y, ...)
    int width = 960, height = 600;
    std::string data;            // the text of a data file
};

// Counts, for each series, the later series on its axis that share a point
// with it (PlotSeries::beneath), so lines that coincide all show.
void mark_beneath(std::vector<PlotSeries>& all);

// Ticks for a log axis over [low, high]: 1, 2 and 5 times the powers of ten
// inside it; only the powers of ten when that would be more than nine ticks,
// every integer times them when fewer than three.
std::vector<std::pair<double, std::string>> log_ticks(double low, double high);
// Integer ticks from 0 (or 'low') to 'high', a step of 1, 2, 4, 5, 8 or a
// multiple of 5 or 10 so that there are at most about eight.
std::vector<std::pair<double, std::string>> integer_ticks(double low, double high);
// Ticks at the given values (the swept values of an axis), printed plainly.
std::vector<std::pair<double, std::string>> value_ticks(std::vector<double> values);
// A log axis's range over values from 'low' to 'high', padded by 'pad' (a
// factor) on each side so no point sits on the border.
std::pair<double, double> padded_log_range(double low, double high, double pad = 1.25);

// A data file (crossover.csv): no template, only its text.
Figure data_file(const std::string& file, const std::string& text);

std::string number_text(double v);   // "%.10g"
std::string short_number(double v);  // three significant digits below 100, whole numbers above: "0.142", "12340"

// The gnuplot text that draws 'figure' into 'png_path': its variables and
// data blocks, then figures/common.gp, then figures/TEMPLATE.gp.
std::string figure_script(const Figure& figure, const std::string& png_path);

}  // namespace cdvp
