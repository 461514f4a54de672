#include "sw/study/fidelity_figure.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace cdvp {

Figure fidelity_figure(const std::vector<FidelityPoint>& levels, const std::string& context) {
    Figure figure;
    figure.file = "fidelity.png";
    figure.template_name = "fidelity";
    double worst = 0, least = INFINITY, fastest = INFINITY, slowest = 0;
    for (const FidelityPoint& level : levels) {
        worst = std::max(worst, level.error_percent);
        if (level.error_percent > 0) least = std::min(least, level.error_percent);
        fastest = std::min(fastest, level.wall_ms_per_frame);
        slowest = std::max(slowest, level.wall_ms_per_frame);
    }
    // Both axes logarithmic. An exact level (error 0, or below a millionth of
    // a percent: summing order) sits on the error axis's floor, a decade below
    // the least error shown, ticked "0".
    const double floor = std::min(1e-3, std::isfinite(least) ? least / 10 : 1e-3);
    const auto shown_error = [&](double error) { return error > 1e-6 && error > floor ? error : floor; };
    figure.x.label = "error of the mean simulated frame time against the reference (%, log; 0: exact)";
    figure.x.log = true;
    figure.x.min = floor / 2;
    // Room right of the worst point for its label (about 45 % of the axis).
    const double data_decades = std::log10(std::max(worst, floor * 10) / figure.x.min);
    figure.x.max = std::max(worst, floor * 10) * std::pow(10.0, 0.85 * data_decades);
    for (const auto& tick : log_ticks(figure.x.min, figure.x.max)) {
        // None far right of the worst error: that stretch is the labels'.
        if (tick.first > floor * 3 && tick.first <= std::max(worst, floor * 10) * 10) figure.x.ticks.push_back(tick);
    }
    figure.x.ticks.insert(figure.x.ticks.begin(), {floor, "0"});
    figure.y.label = "simulator wall time per frame (ms, native; mean over frames)";
    figure.y.log = true;
    std::tie(figure.y.min, figure.y.max) = padded_log_range(fastest, slowest, 2.5);
    // Labels a little right of their points, pushed apart upwards (in log
    // terms) where another label would run over them: one starting within
    // a label's length (about 45 % of the axis) to the left or right.
    const double span = std::log10(figure.y.max / figure.y.min), x_span = std::log10(figure.x.max / figure.x.min);
    const double gap = 0.06 * span, near = 0.45 * x_span;
    std::vector<std::size_t> order(levels.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return levels[a].wall_ms_per_frame < levels[b].wall_ms_per_frame;
    });
    std::vector<double> label_log(levels.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        const FidelityPoint& level = levels[order[k]];
        double at = std::log10(level.wall_ms_per_frame);
        for (std::size_t j = 0; j < k; ++j) {
            const double apart = std::log10(shown_error(levels[order[j]].error_percent) / shown_error(level.error_percent));
            if (std::fabs(apart) < near) at = std::max(at, label_log[order[j]] + gap);
        }
        label_log[order[k]] = at;
    }
    double highest = 0;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const FidelityPoint& level = levels[k];
        PlotSeries s;
        s.title = level.level;
        s.style = series_style(k, levels.size(), 0, 1);
        const double x = shown_error(level.error_percent);
        SeriesPoint p{x, level.wall_ms_per_frame};
        p.label = level.level + ": " + short_number(level.wall_ms_per_frame) + " ms, " +
                  (x == floor ? std::string("exact") : "error " + short_number(level.error_percent) + " %");
        p.label_x = x * std::pow(10.0, 0.03 * x_span);
        p.label_y = std::pow(10.0, label_log[k]);
        highest = std::max(highest, p.label_y);
        s.points.push_back(p);
        figure.series.push_back(s);
    }
    figure.y.max = std::max(figure.y.max, highest * std::pow(10.0, gap));
    figure.y.ticks = log_ticks(figure.y.min, figure.y.max);
    figure.title = "cdvp fidelity: simulator cost against timing error, one point per modelling level\n" + context;
    figure.width = 1280;
    figure.height = 800;
    return figure;
}

}  // namespace cdvp
