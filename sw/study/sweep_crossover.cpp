// Where the board starts to win: crossover.csv, and crossover N against m
// for each baseline the board beats somewhere.
#include <algorithm>
#include <cmath>
#include <map>

#include "sw/study/sweep_samples.h"

namespace cdvp::sweep_figures {

Crossover crossover(const std::vector<std::pair<double, double>>& ratios, bool log_ratio) {
    for (std::size_t k = 0; k < ratios.size(); ++k) {
        const auto [n1, s1] = ratios[k];
        if (s1 < 1) continue;
        if (k == 0) return {n1, "measured", {n1}};
        const auto [n0, s0] = ratios[k - 1];
        const double t = log_ratio ? -std::log(s0) / (std::log(s1) - std::log(s0)) : (1 - s0) / (s1 - s0);
        return {std::exp(std::log(n0) + t * (std::log(n1) - std::log(n0))), "interpolated", {n0, n1}};
    }
    Crossover none;
    for (const auto& [n, s] : ratios) none.rests_on.push_back(n);
    return none;
}

Crossover lasting_crossover(const std::vector<std::pair<double, double>>& ratios) {
    std::size_t last_below = 0;
    for (std::size_t k = 0; k < ratios.size(); ++k) {
        if (ratios[k].second < 1) last_below = k;
    }
    // From the last N below 1 on, the first that reaches 1 is the next.
    return crossover({ratios.begin() + static_cast<std::ptrdiff_t>(last_below), ratios.end()}, true);
}

namespace {

// Whether any of the points a crossover rests on took its software timing
// disturbed: such a crossover is never written as plainly measured.
bool rests_on_disturbed(const Samples& samples, const std::string& board, const Line& line, const Crossover& c,
                        const std::string& baseline) {
    for (const Sample& s : samples.all) {
        if (s.board != board || s.variant != line.variant || s.m != line.m) continue;
        if (std::find(c.rests_on.begin(), c.rests_on.end(), s.n) == c.rests_on.end()) continue;
        if (text(s.row, baseline + "_timing_quality") == "disturbed") return true;
    }
    return false;
}

// m across: integer ticks at the values swept. A log axis when they span a
// factor of 4 or more (1, 2, 4, ... 24); one m alone sits in the middle of
// an axis one step either side of it, not on a sliver around it.
PlotAxis m_axis(const std::vector<PlotSeries>& all) {
    std::vector<double> ms;
    for (const PlotSeries& s : all) {
        for (const SeriesPoint& p : s.points) ms.push_back(p.x);
    }
    PlotAxis axis;
    axis.label = "m (2m-1 comparison lanes)";
    axis.ticks = value_ticks(ms);
    const double low = axis.ticks.front().first, high = axis.ticks.back().first;
    if (low == high) {
        axis.min = low - 1;
        axis.max = high + 1;
    } else if (low > 0 && high / low >= 4) {
        axis.log = true;
        std::tie(axis.min, axis.max) = padded_log_range(low, high, 1.2);
    } else {
        const double pad = (high - low) / 10;
        axis.min = low - pad;
        axis.max = high + pad;
    }
    return axis;
}

// Each point's label above it, or below it where another series' point at
// the same m lies higher (so two labels at one m do not meet).
void place_labels(std::vector<PlotSeries>& all, const PlotAxis& y) {
    const double step = std::pow(y.max / y.min, 0.05);
    for (PlotSeries& s : all) {
        for (SeriesPoint& p : s.points) {
            bool highest = true;
            for (const PlotSeries& other : all) {
                for (const SeriesPoint& q : other.points) highest &= !(q.x == p.x && q.y > p.y);
            }
            p.label_y = highest ? p.y * step : p.y / step;
        }
    }
}

Figure crossover_figure(const std::string& baseline, std::vector<PlotSeries> all,
                        const std::vector<const Sample*>& points,
                        const std::vector<std::pair<std::string, std::string>>& never) {
    Figure figure;
    figure.file = "crossover-" + file_part(baseline) + ".png";
    figure.template_name = "crossover";
    figure.series = std::move(all);
    figure.x = m_axis(figure.series);
    figure.y.label = "N where the board starts to win";
    figure.y.log = true;
    double low = INFINITY, high = -INFINITY;
    for (const PlotSeries& s : figure.series) {
        for (const SeriesPoint& p : s.points) low = std::min(low, p.y), high = std::max(high, p.y);
    }
    // Room above and below each point for its label.
    std::tie(figure.y.min, figure.y.max) = padded_log_range(low, high, 1.6);
    figure.y.ticks = log_ticks(figure.y.min, figure.y.max);
    place_labels(figure.series, figure.y);
    // "adm-xrc-ii at m=1, 2; pcie-gen3-x8 at m=1"
    std::string never_words;
    for (std::size_t k = 0; k < never.size(); ++k) {
        const bool same_line = k > 0 && never[k].first == never[k - 1].first;
        never_words += same_line ? ", " + never[k].second
                                 : (k == 0 ? "" : "; ") + never[k].first + " at m=" + never[k].second;
    }
    figure.title = "smallest N at which the board beats " + baseline_words(baseline) + ", against m\n" +
                   "interpolated in log N between the measured N around it (crossover.csv); "
                   "'<= N': ahead already at the sweep's smallest N\n" +
                   (never_words.empty() ? "" : "never ahead at any N of the sweep: " + never_words + "\n") +
                   board_words(points) + "\n" + run_words(points) + "\n" + software_words(points, {baseline});
    figure.height = 680;
    return figure;
}

}  // namespace

void add_crossovers(const Samples& samples, const std::vector<std::string>& variant_axes,
                    const std::vector<std::string>& baselines, FigurePlan& plan) {
    std::string csv = "board,m,";
    for (const std::string& axis : variant_axes) csv += axis + ",";
    csv += "baseline,crossover_n,how,timing,energy_crossover_n,energy_how\n";
    for (const std::string& baseline : baselines) {
        std::vector<PlotSeries> drawn;
        std::vector<const Sample*> behind;  // the points the figure rests on
        std::vector<std::pair<std::string, std::string>> never;  // (line, m) that never cross
        for (std::size_t b = 0; b < samples.boards.size(); ++b) {
            const std::string& board = samples.boards[b];
            // One line per variant: crossover N against m.
            std::map<std::string, PlotSeries> by_variant;
            // Where the board starts to take less energy a frame than the
            // software (docs/energy.md), found the same way.
            const Series energy = series(samples, board, baseline + "_energy_ratio", 1);
            for (const auto& [key, line] : series(samples, board, baseline + "_speedup", 1)) {
                const Crossover c = crossover(line.points);
                const auto energy_line = energy.find(key);
                const Crossover e = energy_line != energy.end() ? crossover(energy_line->second.points) : Crossover{};
                std::string values;
                for (const Sample& s : samples.all) {
                    if (s.board == board && s.variant == line.variant) {
                        for (const std::string& v : s.variant_values) values += v + ",";
                        break;
                    }
                }
                const bool disturbed = rests_on_disturbed(samples, board, line, c, baseline);
                csv += board + "," + num(line.m) + "," + values + baseline + "," + (c.n > 0 ? num(c.n) : "") + "," +
                       c.how + (disturbed ? " (disturbed timing)" : "") + "," + (disturbed ? "disturbed" : "clean") + "," +
                       (e.n > 0 ? num(e.n) : "") + "," + e.how + "\n";
                PlotSeries& variant_line = by_variant[key.first];
                variant_line.title = line.variant.empty() ? board : board + " " + line.variant;
                // A colour per board, a dash per variant (or the other way about).
                variant_line.style = series_style(b, samples.boards.size(), line.variant_place, samples.variants);
                if (c.n == 0) never.push_back({variant_line.title, num(line.m)});
                if (c.n > 0) {
                    const bool at_smallest = std::string(c.how) == "measured";
                    // A crossover from a disturbed timing is labelled so on the figure too.
                    variant_line.points.push_back({line.m, c.n,
                                                   (at_smallest ? "<= " : "") + short_number(c.n) + (disturbed ? " (disturbed)" : "")});
                }
            }
            for (auto& [order, line] : by_variant) {
                if (!line.points.empty()) drawn.push_back(line);
            }
            if (!by_variant.empty()) {
                const std::vector<const Sample*> its = on_board(samples, board);
                behind.insert(behind.end(), its.begin(), its.end());
            }
        }
        if (drawn.empty()) {
            plan.notes.push_back("no crossover plot against " + baseline + ": the board beats it at no N of the sweep");
            continue;
        }
        plan.figures.push_back(crossover_figure(baseline, drawn, behind, never));
    }
    plan.figures.push_back(data_file("crossover.csv", csv));
}

}  // namespace cdvp::sweep_figures
