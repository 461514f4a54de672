#include "sw/study/fidelity_figure.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace cdvp {

Figure fidelity_figure(const std::vector<FidelityPoint>& levels, const std::string& context) {
    Figure figure;
    figure.file = "fidelity.png";
    figure.template_name = "fidelity";
    double worst = 0, fastest = INFINITY, slowest = 0;
    for (const FidelityPoint& level : levels) {
        worst = std::max(worst, level.error_percent);
        fastest = std::min(fastest, level.wall_ms_per_frame);
        slowest = std::max(slowest, level.wall_ms_per_frame);
    }
    // From 0, to a little past the worst error; 1 % when every level is exact.
    figure.x.label = "error of the mean simulated frame time against the reference (%)";
    figure.x.min = 0;
    figure.x.max = worst > 0 ? worst * 1.6 : 1;
    figure.y.label = "simulator wall time per frame (ms, native; median over frames)";
    figure.y.log = true;
    std::tie(figure.y.min, figure.y.max) = padded_log_range(fastest, slowest, 2.5);
    // Labels a little right of their points, pushed apart upwards (in log
    // terms) where another label would run over them: one starting within
    // a label's length (about 45 % of the axis) to the left or right.
    const double span = std::log10(figure.y.max / figure.y.min);
    const double gap = 0.06 * span, near = 0.45 * figure.x.max;
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
            if (std::fabs(levels[order[j]].error_percent - level.error_percent) < near) {
                at = std::max(at, label_log[order[j]] + gap);
            }
        }
        label_log[order[k]] = at;
    }
    double highest = 0;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const FidelityPoint& level = levels[k];
        PlotSeries s;
        s.title = level.level;
        s.style = series_style(k, levels.size(), 0, 1);
        SeriesPoint p{level.error_percent, level.wall_ms_per_frame};
        p.label = level.level + ": " + short_number(level.wall_ms_per_frame) + " ms, error " +
                  short_number(level.error_percent) + " %";
        p.label_x = level.error_percent + 0.04 * figure.x.max;
        p.label_y = std::pow(10.0, label_log[k]);
        highest = std::max(highest, p.label_y);
        s.points.push_back(p);
        figure.series.push_back(s);
    }
    figure.y.max = std::max(figure.y.max, highest * std::pow(10.0, gap));
    figure.y.ticks = log_ticks(figure.y.min, figure.y.max);
    figure.title = "cdvp fidelity: simulator cost against timing error, one point per modelling level\n" + context;
    return figure;
}

}  // namespace cdvp
