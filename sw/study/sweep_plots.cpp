#include "sw/study/sweep_plots.h"

#include "sw/study/sweep_samples.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <tuple>

namespace cdvp {

namespace sweep_figures {

std::string Line::title() const {
    const std::string m_part = "m=" + num(m);
    return variant.empty() ? m_part : m_part + " " + variant;
}

Series series(const Samples& samples, const std::string& board, const std::string& column, double scale) {
    Series lines;
    for (const Sample& s : samples.all) {
        const double y = number(s.row, column);
        if (s.board != board || std::isnan(y)) continue;
        Line& line = lines[{s.variant_order, s.m}];
        line.m = s.m;
        line.variant = s.variant;
        line.m_place = s.m_place;
        line.variant_place = s.variant_place;
        line.points.push_back({s.n, y * scale});
    }
    for (auto& [key, line] : lines) std::sort(line.points.begin(), line.points.end());
    return lines;
}

std::vector<PlotSeries> board_series(const Series& lines, const Samples& samples) {
    std::vector<PlotSeries> all;
    for (const auto& [key, line] : lines) {
        PlotSeries s;
        s.title = line.title();
        s.style = series_style(line.m_place, samples.ms, line.variant_place, samples.variants);
        for (const auto& [x, y] : line.points) s.points.push_back({x, y});
        all.push_back(s);
    }
    return all;
}

double number(const RowView& row, const std::string& column) {
    const std::string value = row.get(column);
    return value.empty() ? std::nan("") : std::strtod(value.c_str(), nullptr);
}

std::string text(const RowView& row, const std::string& column) { return row.get(column); }

std::string file_part(std::string s) {
    for (char& c : s) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+') c = '-';
    }
    return s;
}

std::string num(double v) { return number_text(v); }

// The extremes of every y over the series.
std::pair<double, double> y_extent(const std::vector<PlotSeries>& all) {
    double low = INFINITY, high = -INFINITY;
    for (const PlotSeries& s : all) {
        for (const SeriesPoint& p : s.points) {
            low = std::min(low, p.y);
            high = std::max(high, p.y);
        }
    }
    return {low, high};
}

// N on a log axis that just holds the points, ticked at the swept values.
PlotAxis n_axis(const std::vector<const Sample*>& points) {
    PlotAxis axis;
    axis.label = "N (objects)";
    axis.log = true;
    std::vector<double> ns;
    for (const Sample* s : points) ns.push_back(s->n);
    const auto [low, high] = std::minmax_element(ns.begin(), ns.end());
    std::tie(axis.min, axis.max) = padded_log_range(*low, *high, 1.15);
    axis.ticks = value_ticks(ns);
    if (axis.ticks.size() > 12) axis.ticks = log_ticks(axis.min, axis.max);
    return axis;
}

// A log y axis over the series, padded, with ticks a reader can read off.
PlotAxis log_y_axis(const std::string& label, const std::vector<PlotSeries>& all, double include) {
    PlotAxis axis;
    axis.label = label;
    axis.log = true;
    auto [low, high] = y_extent(all);
    if (!std::isnan(include)) low = std::min(low, include), high = std::max(high, include);
    std::tie(axis.min, axis.max) = padded_log_range(low, high, 1.3);
    axis.ticks = log_ticks(axis.min, axis.max);
    return axis;
}

}  // namespace sweep_figures

namespace {

using namespace sweep_figures;

// Each baseline's time at each N: the median over the board's points there
// (every point times the same software on the same frames; a median keeps
// one disturbed point from bending the line).
std::vector<PlotSeries> baseline_series(const Samples& samples, const std::string& board,
                                        const std::vector<std::string>& baselines, double scale) {
    std::vector<PlotSeries> all;
    for (std::size_t b = 0; b < baselines.size(); ++b) {
        std::map<double, std::vector<double>> by_n;
        for (const Sample* s : on_board(samples, board)) {
            const double t = number(s->row, baselines[b] + "_mean_host_ns");
            if (!std::isnan(t)) by_n[s->n].push_back(t * scale);
        }
        if (by_n.empty()) continue;
        PlotSeries line;
        line.title = "software " + baseline_words(baselines[b]);
        line.style = baseline_style(b);
        for (auto& [n, times] : by_n) {
            std::sort(times.begin(), times.end());
            const std::size_t mid = times.size() / 2;
            line.points.push_back({n, times.size() % 2 ? times[mid] : (times[mid - 1] + times[mid]) / 2});
        }
        all.push_back(line);
    }
    return all;
}

Figure time_figure(const Samples& samples, const std::string& board, const std::vector<std::string>& baselines) {
    const std::vector<const Sample*> points = on_board(samples, board);
    Figure figure;
    figure.file = "time-" + file_part(board) + ".png";
    figure.template_name = "time";
    // Microseconds, or milliseconds once a frame takes 10 ms or more.
    const Series us = series(samples, board, "mean_total_ns", 1e-3);
    std::vector<PlotSeries> all = board_series(us, samples);
    const std::vector<PlotSeries> software = baseline_series(samples, board, baselines, 1e-3);
    all.insert(all.end(), software.begin(), software.end());
    const bool in_ms = y_extent(all).second >= 1e4;
    if (in_ms) {
        for (PlotSeries& s : all) {
            for (SeriesPoint& p : s.points) p.y /= 1e3;
        }
    }
    figure.series = all;
    figure.x = n_axis(points);
    figure.y = log_y_axis(in_ms ? "mean time per frame (ms)" : "mean time per frame (us)", figure.series);
    figure.title = "mean frame time against N on " + board_words(points) + "\n" + run_words(points);
    if (!software.empty()) figure.title += "\n" + software_words(points, baselines);
    return figure;
}

Figure speedup_figure(const Samples& samples, const std::string& board, const std::string& baseline) {
    const std::vector<const Sample*> points = on_board(samples, board);
    Figure figure;
    figure.file = "speedup-" + file_part(board) + "-" + file_part(baseline) + ".png";
    figure.template_name = "speedup";
    figure.series = board_series(series(samples, board, baseline + "_speedup", 1), samples);
    // A speedup that rests on a disturbed software timing is ringed, so a
    // reader does not take its bend for the board's.
    PlotSeries disturbed;
    disturbed.title = "disturbed software timing (docs/timing.md)";
    disturbed.style = mark_style();
    for (const Sample* s : points) {
        const double y = number(s->row, baseline + "_speedup");
        if (!std::isnan(y) && text(s->row, baseline + "_timing_quality") == "disturbed") disturbed.points.push_back({s->n, y});
    }
    std::sort(disturbed.points.begin(), disturbed.points.end(),
              [](const SeriesPoint& a, const SeriesPoint& b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
    if (!disturbed.points.empty()) figure.series.push_back(disturbed);
    figure.x = n_axis(points);
    figure.y = log_y_axis("speedup (x): software's mean frame time / board's", figure.series, 1.0);
    figure.numbers["reference_y"] = 1;
    figure.title = "speedup of " + board_words(points) + " over " + baseline_words(baseline) + "\n" +
                   run_words(points) + "\n" + software_words(points, {baseline});
    return figure;
}

template <class T>
std::vector<T> sorted_unique(std::vector<T> values) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    return values;
}

// Each sample's place among the sweep's values of m and its variants, so a
// series keeps its style from one figure to the next.
void place_samples(Samples& samples) {
    std::vector<double> ms;
    std::vector<std::string> variants;
    for (const Sample& s : samples.all) {
        ms.push_back(s.m);
        variants.push_back(s.variant_order);
    }
    ms = sorted_unique(ms);
    variants = sorted_unique(variants);
    for (Sample& s : samples.all) {
        s.m_place = std::lower_bound(ms.begin(), ms.end(), s.m) - ms.begin();
        s.variant_place = std::lower_bound(variants.begin(), variants.end(), s.variant_order) - variants.begin();
    }
    samples.ms = std::max<std::size_t>(1, ms.size());
    samples.variants = std::max<std::size_t>(1, variants.size());
}

// The axes the figures read, each by what it sets, whatever its name (a grid
// named by hand keys its axes by name); every other axis that varies draws
// lines of its own, a variant.
struct PlotAxes {
    const Axis* board = nullptr;
    const Axis* n = nullptr;
    const Axis* m = nullptr;
    const Axis* scene = nullptr;  // --scene or --trace
    std::vector<const Axis*> variants;
    std::vector<std::string> variant_names;
    // Each variant value's place in its axis, for lines in grid order.
    std::vector<std::map<std::string, std::size_t>> variant_places;
};

PlotAxes plot_axes(const Grid& grid) {
    PlotAxes axes;
    axes.board = grid.find("board");
    axes.n = grid.find("scene.objects") ? grid.find("scene.objects") : grid.find("objects");
    axes.m = grid.find("board.m") ? grid.find("board.m") : grid.find("m");
    axes.scene = grid.find("scene") ? grid.find("scene") : grid.find("trace");
    for (const Axis& axis : grid.axes()) {
        if (&axis == axes.board || &axis == axes.n || &axis == axes.m || axis.values.size() < 2) continue;
        axes.variants.push_back(&axis);
        axes.variant_names.push_back(axis.name);
        axes.variant_places.emplace_back();
        for (std::size_t k = 0; k < axis.values.size(); ++k) axes.variant_places.back().emplace(axis.values[k], k);
    }
    return axes;
}

// One sample per point that ran, with its board, m, N and variant.
Samples collect_samples(const PlotAxes& axes, const SweepTable& table) {
    Samples samples;
    table.for_each([&](std::size_t, const RowView& row) {
        if (text(row, "status") != "ok") return;
        Sample s;
        s.board = text(row, axes.board ? axes.board->name : "config.board");
        s.m = number(row, axes.m ? axes.m->name : "config.m");
        s.n = number(row, axes.n ? axes.n->name : "median_objects");
        s.row = row;
        // A row's source reads "spheres objects=100 seed=1": the scene is its first word.
        const std::string source = text(row, "config.source");
        s.scene = axes.scene ? text(row, axes.scene->name) : source.substr(0, source.find(' '));
        s.algorithm = text(row, "config.settings.board.algorithm.value");
        s.format = text(row, "config.format");
        for (std::size_t v = 0; v < axes.variants.size(); ++v) {
            const Axis* axis = axes.variants[v];
            const std::string value = text(row, axis->name);
            const auto at = axes.variant_places[v].find(value);
            const std::size_t place = at == axes.variant_places[v].end() ? axis->values.size() : at->second;
            char order[16];
            std::snprintf(order, sizeof order, "%08zu|", place);
            s.variant += (s.variant.empty() ? "" : " ") + axis->name + "=" + value;
            s.variant_order += order;
            s.variant_values.push_back(value);
            if (axis->key == "board.algorithm") {
                s.algorithm = value;
            } else if (axis->key == "board.format") {
                s.format = value;
            } else if (axis != axes.scene) {
                s.setup += (s.setup.empty() ? "" : " ") + axis->name + "=" + value;
            }
        }
        if (std::find(samples.boards.begin(), samples.boards.end(), s.board) == samples.boards.end()) {
            samples.boards.push_back(s.board);
        }
        samples.all.push_back(s);
    });
    return samples;
}

}  // namespace

FigurePlan plan_figures(const Grid& grid, const SweepTable& table) {
    FigurePlan plan;
    const PlotAxes axes = plot_axes(grid);
    const Axis* n_axis = axes.n;
    const std::vector<std::string>& variant_names = axes.variant_names;
    Samples samples = collect_samples(axes, table);
    if (samples.all.empty()) {
        plan.notes.push_back("no plots: no point of the sweep ran");
        return plan;
    }
    place_samples(samples);
    std::vector<std::string> baselines;
    for (const std::string& column : table.columns()) {
        if (column.size() > 8 && column.compare(column.size() - 8, 8, "_speedup") == 0) {
            baselines.push_back(column.substr(0, column.size() - 8));
        }
    }
    add_phase_figures(samples, plan);
    add_fit_figures(samples, variant_names, plan);
    add_answer(samples, baselines, plan);
    if (n_axis == nullptr) {
        plan.notes.push_back("no plots against N (time, speedup, crossover): objects (or scene.objects) is not an axis of this sweep");
        return plan;
    }
    if (baselines.empty()) {
        const bool asked = std::any_of(samples.all.begin(), samples.all.end(),
                                       [](const Sample& s) { return !text(s.row, "config.baselines").empty(); });
        plan.notes.push_back(asked ? "no speedup or crossover plots: no point timed a frame (--frames 0)"
                                   : "no speedup or crossover plots: the sweep has no --baseline");
    }
    for (const std::string& board : samples.boards) {
        if (series(samples, board, "mean_total_ns", 1).empty()) {
            plan.notes.push_back("no plots of time or speedup on " + board + ": no point timed a frame (--frames 0)");
            continue;
        }
        plan.figures.push_back(time_figure(samples, board, baselines));
        for (const std::string& baseline : baselines) {
            if (series(samples, board, baseline + "_speedup", 1).empty()) continue;
            plan.figures.push_back(speedup_figure(samples, board, baseline));
        }
    }
    if (!baselines.empty()) add_crossovers(samples, variant_names, baselines, plan);
    return plan;
}

}  // namespace cdvp
