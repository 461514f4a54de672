// Where a frame's time goes: each phase's share of the board's mean frame,
// a stacked bar per point. Shares, because the frames of one sweep span
// decades (50 boxes at m = 24 against 2,000 at m = 1): on one linear axis of
// time every bar but the slowest would be a sliver. Each bar's label gives
// the whole frame's time, so no figure is lost.
#include <algorithm>
#include <cmath>

#include "sw/study/sweep_samples.h"

namespace cdvp::sweep_figures {

namespace {

// The phases of a frame in the order it goes through them; their means add
// up to the mean frame (what extra pairs cost is a part of readback and
// driver, so it is not a phase of its own).
const std::vector<std::string> kFramePhases{"upload", "start", "compute", "irq", "readback", "driver"};

// A phase's mean time in the row; 0 for one it does not have.
double phase_ns(const Sample& s, const std::string& phase) {
    const double ns = number(s.row, "mean_" + phase + "_ns");
    return std::isnan(ns) ? 0 : ns;
}

double frame_ns(const Sample& s) {
    double frame = 0;
    for (const std::string& phase : kFramePhases) frame += phase_ns(s, phase);
    return frame;
}

Figure phase_figure(const std::string& board, std::vector<const Sample*> bars) {
    // By variant, then m, then N: the bars of one variant and m side by side.
    std::stable_sort(bars.begin(), bars.end(), [](const Sample* a, const Sample* b) {
        if (a->variant_order != b->variant_order) return a->variant_order < b->variant_order;
        return a->m != b->m ? a->m < b->m : a->n < b->n;
    });
    Figure figure;
    figure.file = "phases-" + file_part(board) + ".png";
    figure.template_name = "phases";
    for (std::size_t k = 0; k < kFramePhases.size(); ++k) {
        PlotSeries phase;
        phase.title = kFramePhases[k];
        phase.style = series_style(k, kFramePhases.size(), 0, 1);
        figure.series.push_back(phase);
    }
    double x = 0;
    std::size_t longest = 0;
    for (std::size_t b = 0; b < bars.size(); ++b) {
        const Sample& s = *bars[b];
        // A gap between groups of one variant and m.
        if (b > 0 && (s.variant_order != bars[b - 1]->variant_order || s.m != bars[b - 1]->m)) x += 1;
        x += 1;
        const double frame = frame_ns(s);
        double base = 0;
        for (std::size_t k = 0; k < kFramePhases.size(); ++k) {
            const double share = 100 * phase_ns(s, kFramePhases[k]) / frame;
            SeriesPoint bar(x, base + share);
            bar.base = base;
            figure.series[k].points.push_back(bar);
            base += share;
        }
        const std::string label = "N=" + num(s.n) + " m=" + num(s.m) + (s.variant.empty() ? "" : " " + s.variant) +
                                  ": " + frame_time_words(number(s.row, "mean_total_ns"));
        longest = std::max(longest, label.size());
        figure.x.ticks.push_back({x, label});
    }
    const bool variants = std::any_of(bars.begin(), bars.end(), [](const Sample* s) { return !s->variant.empty(); });
    figure.x.label = variants ? "each bar: N, m, variant: the mean frame time" : "each bar: N, m: the mean frame time";
    figure.x.min = 0;
    figure.x.max = x + 1;
    figure.y.label = "share of the mean frame (%)";
    figure.y.min = 0;
    figure.y.max = 100;
    figure.y.ticks = integer_ticks(0, 100);
    // Room for every bar and for its label, written upright at font 8.
    figure.width = std::max(960, static_cast<int>(x) * 18 + 260);
    figure.height = 560 + static_cast<int>(longest) * 5;
    const std::vector<const Sample*> points(bars.begin(), bars.end());
    figure.title = "where the board's frame time goes on " + board_words(points) +
                   ": each phase's share of the mean frame\n" + run_words(points);
    return figure;
}

}  // namespace

std::string frame_time_words(double ns) {
    if (ns >= 1e9) return short_number(ns / 1e9) + " s";
    if (ns >= 1e6) return short_number(ns / 1e6) + " ms";
    return short_number(ns / 1e3) + " us";
}

void add_phase_figures(const Samples& samples, FigurePlan& plan) {
    for (const std::string& board : samples.boards) {
        std::vector<const Sample*> bars;
        for (const Sample* s : on_board(samples, board)) {
            if (frame_ns(*s) > 0) bars.push_back(s);  // a point that timed no frame has no shares
        }
        if (bars.empty()) {
            plan.notes.push_back("no phase plot on " + board + ": no point timed a frame (--frames 0)");
            continue;
        }
        plan.figures.push_back(phase_figure(board, bars));
    }
}

}  // namespace cdvp::sweep_figures
