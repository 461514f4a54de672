// What fits the device: fit.csv, the largest m against N, and the lanes a
// number format buys against the extra pairs it costs.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "sw/study/sweep_samples.h"

namespace cdvp::sweep_figures {

namespace {

// The extra pairs a number format adds, as a share of the float32
// reference's pairs; NaN when the report has no such figures.
double extra_share(const RowView& row) {
    const double extra = number(row, "median_extra_pairs");
    const double reference = number(row, "median_reference_pairs");
    if (std::isnan(extra) || std::isnan(reference)) return std::nan("");
    return reference > 0 ? extra / reference : 0.0;
}

// What fits at one (board, variant, N).
struct Fit {
    const Sample* any = nullptr;      // a point that ran there
    const Sample* at_best = nullptr;  // the point at the largest m, when the sweep ran it
    double largest_m = std::nan("");
};

std::string variant_label(const Sample& s) {
    std::string label;
    for (const std::string& v : s.variant_values) label += (label.empty() ? "" : "/") + v;
    return label;
}

// Largest m against N, one series per variant; variants whose m agree at
// every N share one series, named by all of them, so none hides another.
Figure largest_m_figure(const std::string& board, const std::vector<const Sample*>& points,
                        const std::map<std::string, Line>& by_variant) {
    std::vector<std::pair<std::vector<std::pair<double, double>>, std::vector<std::string>>> groups;
    for (const auto& entry : by_variant) {
        const Line& line = entry.second;
        const auto same = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == line.points; });
        const std::string name = line.variant.empty() ? board : line.variant;
        if (same == groups.end()) {
            groups.push_back({line.points, {name}});
        } else {
            same->second.push_back(name);
        }
    }
    Figure figure;
    figure.file = "largest-m-" + file_part(board) + ".png";
    figure.template_name = "largest_m";
    double highest = 0;
    for (std::size_t k = 0; k < groups.size(); ++k) {
        PlotSeries s;
        s.style = series_style(k, groups.size(), 0, 1);
        // "format=float32, format=fixed32" reads as "format=float32, fixed32".
        std::string title;
        for (const std::string& name : groups[k].second) {
            const std::size_t eq = name.find('=');
            const bool same_axis = !title.empty() && eq != std::string::npos && title.find(name.substr(0, eq + 1)) == 0;
            title += (title.empty() ? "" : ", ") + (same_axis ? name.substr(eq + 1) : name);
        }
        s.title = title;
        for (const auto& [n, m] : groups[k].first) {
            // Each value written by its point (11 and 12 look alike on the
            // axis), once where series meet.
            bool labelled = false;
            for (const PlotSeries& before : figure.series) {
                for (const SeriesPoint& p : before.points) labelled |= p.x == n && p.y == m;
            }
            s.points.push_back({n, m, labelled ? "" : num(m)});
            highest = std::max(highest, m);
        }
        figure.series.push_back(s);
    }
    mark_beneath(figure.series);
    std::vector<double> ns;
    for (const Sample* s : points) ns.push_back(s->n);
    figure.x.label = "N (objects)";
    figure.x.log = true;
    const auto [low, high] = std::minmax_element(ns.begin(), ns.end());
    std::tie(figure.x.min, figure.x.max) = padded_log_range(*low, *high, 1.15);
    figure.x.ticks = value_ticks(ns);
    if (figure.x.ticks.size() > 12) figure.x.ticks = log_ticks(figure.x.min, figure.x.max);
    // An integer from 0: integer ticks, and room above the highest step.
    figure.y.label = "largest m that fits (2m-1 lanes)";
    figure.y.min = 0;
    figure.y.max = std::ceil(highest * 1.12 + 0.5);
    figure.y.ticks = integer_ticks(0, figure.y.max);
    const std::string device = text(points.front()->row, "config.settings.device.name.value");
    figure.title = "largest m that fits " + board_words(points) + (device.empty() ? "" : " on its " + device) +
                   " (fit.csv)\n" +
                   "at each measured N; each flat step is an m that fits every N up to the step's end";
    return figure;
}

// The variants along x (in grid order): the lanes that fit above, the extra
// pairs below on a log axis whose bottom row is 0 %, one line per N; at most
// kMostN values of N, spread from the smallest to the largest.
Figure lanes_extra_figure(const std::string& board, const std::string& variant_names, const std::vector<const Sample*>& points,
                          std::map<double, std::vector<std::pair<const Sample*, double>>> frontier, FigurePlan& plan) {
    constexpr std::size_t kMostN = 4;
    std::vector<double> drawn_n;
    for (const auto& [n, at] : frontier) drawn_n.push_back(n);
    if (drawn_n.size() > kMostN) {
        std::vector<double> spread;
        for (std::size_t i = 0; i < kMostN; ++i) spread.push_back(drawn_n[i * (drawn_n.size() - 1) / (kMostN - 1)]);
        plan.notes.push_back("lanes-extra-" + file_part(board) + ".png shows " + std::to_string(kMostN) + " of the " +
                             std::to_string(drawn_n.size()) + " values of N (fit.csv has them all)");
        drawn_n = spread;
    }
    Figure figure;
    figure.file = "lanes-extra-" + file_part(board) + ".png";
    figure.template_name = "lanes_extra";
    figure.height = 760;
    double most_lanes = 0, least_share = INFINITY, most_share = 0;
    for (const auto& [n, at] : frontier) {
        for (const auto& [s, lanes] : at) {
            const double share = 100 * extra_share(s->row);
            most_lanes = std::max(most_lanes, lanes);
            most_share = std::max(most_share, share);
            if (share > 0) least_share = std::min(least_share, share);
        }
    }
    // Zero has no place on a log axis: it gets the row a decade under the
    // smallest share, ticked "0", below a dotted line.
    const double floor_decade = std::pow(10.0, std::floor(std::log10(std::isinf(least_share) ? 1.0 : least_share)));
    const double zero_at = floor_decade / 10;
    // Each variant's place along x, in grid order, whichever N it ran at.
    std::map<std::string, std::pair<double, std::string>> places;
    for (const auto& [n, at] : frontier) {
        for (const auto& [s, lanes] : at) places[s->variant_order].second = variant_label(*s);
    }
    double place = 0;
    for (auto& [order, at] : places) {
        at.first = ++place;
        figure.x.ticks.push_back(at);
    }
    for (std::size_t k = 0; k < drawn_n.size(); ++k) {
        PlotSeries lanes, extra;
        lanes.title = extra.title = "N=" + num(drawn_n[k]);
        lanes.style = series_style(k, drawn_n.size(), 0, 2);
        extra.style = series_style(k, drawn_n.size(), 1, 2);
        extra.second_axis = true;
        // The variants are categories, so each N's points may stand a little
        // apart within one: equal values at several N then all show.
        const double dodge = (static_cast<double>(k) - (drawn_n.size() - 1) / 2.0) * 0.05;
        for (const auto& [s, lane_count] : frontier[drawn_n[k]]) {
            const double x = places[s->variant_order].first + dodge;
            const double share = 100 * extra_share(s->row);
            lanes.points.push_back({x, lane_count});
            extra.points.push_back({x, share > 0 ? share : zero_at});
        }
        figure.series.push_back(lanes);
        figure.series.push_back(extra);
    }
    figure.x.label = variant_names;
    figure.x.min = 0.5;
    figure.x.max = place + 0.5;
    figure.y.label = "lanes (2m-1) that fit";
    figure.y.min = 0;
    figure.y.max = std::ceil(most_lanes * 1.12 + 0.5);
    figure.y.ticks = integer_ticks(0, figure.y.max);
    figure.y2.label = "extra pairs (% of the float32 reference)";
    figure.y2.log = true;
    figure.y2.min = zero_at / 2;
    figure.y2.max = std::max(most_share, floor_decade) * 2;
    figure.y2.ticks = log_ticks(floor_decade, figure.y2.max);
    figure.y2.ticks.insert(figure.y2.ticks.begin(), {zero_at, "0"});
    figure.numbers["zero_line"] = std::sqrt(zero_at * floor_decade);
    figure.title = "lanes that fit " + board_words(points) + " and the extra pairs of each number format (fit.csv)\n" +
                   run_words(points);
    return figure;
}

}  // namespace

void add_fit_figures(const Samples& samples, const std::vector<std::string>& variant_axes, FigurePlan& plan) {
    // board -> (variant order, N) -> fit
    std::map<std::string, std::map<std::pair<std::string, double>, Fit>> fits;
    for (const Sample& s : samples.all) {
        const double largest = number(s.row, "config.resources.largest_m");
        if (std::isnan(largest)) continue;
        Fit& fit = fits[s.board][{s.variant_order, s.n}];
        fit.any = &s;
        fit.largest_m = largest;
        if (s.m == largest) fit.at_best = &s;
    }
    if (fits.empty()) {
        plan.notes.push_back("no fit.csv: the points' reports have no config.resources.largest_m (no device family)");
        return;
    }
    std::string csv = "board,";
    for (const std::string& axis : variant_axes) csv += axis + ",";
    csv += "objects,largest_m,lanes,extra_pair_share,board_median_total_ns\n";
    for (const std::string& board : samples.boards) {
        if (fits[board].empty()) continue;
        std::map<std::string, Line> largest_by_variant;
        // Lanes against extra pairs: one line per N, one point per variant.
        std::map<double, std::vector<std::pair<const Sample*, double>>> frontier;
        for (const auto& [key, fit] : fits[board]) {
            const Sample& s = *fit.any;
            const double lanes = fit.largest_m > 0 ? 2 * fit.largest_m - 1 : 0;
            const double share = extra_share(s.row);
            csv += board + ",";
            for (const std::string& v : s.variant_values) csv += v + ",";
            csv += num(s.n) + "," + num(fit.largest_m) + "," + num(lanes) + "," + (std::isnan(share) ? "" : num(share)) +
                   "," + (fit.at_best ? text(fit.at_best->row, "median_total_ns") : "") + "\n";
            Line& line = largest_by_variant[key.first];
            line.variant = s.variant;
            line.points.push_back({s.n, fit.largest_m});
            if (!std::isnan(share) && !s.variant.empty()) frontier[s.n].push_back({&s, lanes});
        }
        const std::vector<const Sample*> points = on_board(samples, board);
        plan.figures.push_back(largest_m_figure(board, points, largest_by_variant));
        std::string names;
        for (const std::string& axis : variant_axes) names += (names.empty() ? "" : "/") + axis;
        if (!frontier.empty()) plan.figures.push_back(lanes_extra_figure(board, names, points, frontier, plan));
    }
    plan.figures.push_back(data_file("fit.csv", csv));
}

}  // namespace cdvp::sweep_figures
