// The answer's figures: time a frame and energy a frame against N, a line per
// board configuration that is the fastest at some N, the fastest software's
// line, and the crossover drawn where the board starts to win.
#include <algorithm>

#include "sw/study/sweep_answer.h"

namespace cdvp::sweep_figures {

namespace {

// The quantity a figure draws: its file, its words and how to read it off a point.
struct Quantity {
    std::string file, what;   // "answer-time", "time"
    std::string row_column;   // the board's column in a row
    double AnswerPoint::*software;
    const AnswerCrossover SceneAnswer::*crossover;
    std::string winning;      // "faster", "takes less energy"
};

// The same configuration as the answer's point: the samples of one line.
bool same_configuration(const Sample& s, const Sample& as) {
    return s.scene == as.scene && s.board == as.board && s.m == as.m && s.algorithm == as.algorithm &&
           s.format == as.format && s.setup == as.setup;
}

// A unit that keeps the largest value under a thousand: {scale, name}.
std::pair<double, std::string> unit_of(const Quantity& q, double largest) {
    if (q.file == "answer-time") {
        return largest >= 1e7 ? std::pair{1e-6, "ms"} : std::pair{1e-3, "us"};
    }
    return largest >= 1 ? std::pair{1.0, "J"} : largest >= 1e-3 ? std::pair{1e3, "mJ"} : std::pair{1e6, "uJ"};
}

// The crossover as a vertical line from the bottom of the plot to its top,
// its N written at the top.
PlotSeries crossover_mark(const SceneAnswer& answer, const Quantity& q, const PlotAxis& y) {
    const AnswerCrossover& c = answer.*q.crossover;
    PlotSeries mark;
    mark.style = mark_style();
    const std::string n_words = crossover_words(c.at);
    mark.title = "board " + q.winning + " from " + n_words + " on";
    if (q.file == "answer-energy") mark.title += " (" + energy_band_words(answer) + ")";
    mark.points.push_back({c.at.n, y.min});
    mark.points.push_back({c.at.n, y.max, (std::string(c.at.how) == "measured" ? "<= " : "~ ") + short_number(c.at.n)});
    return mark;
}

Figure answer_figure(const Samples& samples, const SceneAnswer& answer, const Quantity& q, bool scene_in_name) {
    Figure figure;
    figure.file = q.file + (scene_in_name ? "-" + file_part(answer.scene) : "") + ".png";
    figure.template_name = "answer";
    // The configurations that are the fastest somewhere, in the order they first win.
    std::vector<const Sample*> winners, points;
    for (const AnswerPoint& a : answer.points) {
        const bool seen = std::any_of(winners.begin(), winners.end(),
                                      [&](const Sample* w) { return same_configuration(*w, *a.board); });
        if (!seen) winners.push_back(a.board);
    }
    for (std::size_t k = 0; k < winners.size(); ++k) {
        PlotSeries line;
        line.style = series_style(k, winners.size(), 0, 1);
        for (const AnswerPoint& a : answer.points) {
            if (same_configuration(*a.board, *winners[k])) line.title = a.configuration;
        }
        line.title += " (fastest board at N = ";
        std::string at;
        for (const AnswerPoint& a : answer.points) {
            if (same_configuration(*a.board, *winners[k])) at += (at.empty() ? "" : ", ") + num(a.n);
        }
        line.title += at + ")";
        for (const Sample& s : samples.all) {
            const double y = number(s.row, q.row_column);
            if (!same_configuration(s, *winners[k]) || !(y > 0)) continue;  // a log axis: none at 0
            line.points.push_back({s.n, y});
            points.push_back(&s);
        }
        std::sort(line.points.begin(), line.points.end(),
                  [](const SeriesPoint& a, const SeriesPoint& b) { return a.x < b.x; });
        if (!line.points.empty()) figure.series.push_back(line);
    }
    PlotSeries software;
    software.style = baseline_style(0);
    std::vector<std::string> names;
    for (const AnswerPoint& a : answer.points) {
        if (a.software.empty() || !(a.*q.software > 0)) continue;
        software.points.push_back({a.n, a.*q.software});
        if (std::find(names.begin(), names.end(), a.software) == names.end()) names.push_back(a.software);
    }
    std::string named;
    for (const std::string& name : names) named += (named.empty() ? "" : ", ") + name;
    software.title = (names.size() == 1 ? "fastest software: " + baseline_words(names[0])
                                        : "fastest software at each N: " + named);
    if (!software.points.empty()) figure.series.push_back(software);
    double largest = 0;
    for (const PlotSeries& s : figure.series) {
        for (const SeriesPoint& p : s.points) largest = std::max(largest, p.y);
    }
    const auto [scale, unit] = unit_of(q, largest);
    for (PlotSeries& s : figure.series) {
        for (SeriesPoint& p : s.points) p.y *= scale;
    }
    mark_beneath(figure.series);
    figure.x = n_axis(points);
    figure.y = log_y_axis(q.what + " a frame (" + unit + ")", figure.series);
    const AnswerCrossover& c = answer.*q.crossover;
    if (c.at.n > 0) figure.series.push_back(crossover_mark(answer, q, figure.y));
    const std::string on = answer.scene.empty() ? "" : " on " + answer.scene;
    if (names.empty()) {
        figure.title = q.what + " a frame against N" + on + ": the fastest board configurations (answer.md)\n" +
                       "no software timed (no --baseline)\n" + board_words(points) + "; " + run_words(points);
        return figure;
    }
    figure.title = q.what + " a frame against N" + on + ": the fastest board configurations and the fastest software (answer.md)\n" +
                   (c.at.n > 0 ? "" : "the board is not " + q.winning + " from any N of the sweep on\n") +
                   board_words(points) + "; " + run_words(points) + "\n" + software_words(points, names);
    return figure;
}

}  // namespace

std::vector<Figure> answer_figures(const Samples& samples, const std::vector<SceneAnswer>& answers) {
    const Quantity quantities[] = {
        {"answer-time", "time", "mean_total_ns", &AnswerPoint::software_ns, &SceneAnswer::time, "faster"},
        {"answer-energy", "energy", "mean_energy_j", &AnswerPoint::software_energy_j, &SceneAnswer::energy,
         "takes less energy"}};
    std::vector<Figure> figures;
    for (const SceneAnswer& answer : answers) {
        for (const Quantity& q : quantities) {
            // None without a value above 0 (no energy without a board's power figures, say).
            const bool drawn = std::any_of(answer.points.begin(), answer.points.end(), [&](const AnswerPoint& a) {
                return number(a.board->row, q.row_column) > 0;
            });
            if (drawn) figures.push_back(answer_figure(samples, answer, q, answers.size() > 1));
        }
    }
    return figures;
}

}  // namespace cdvp::sweep_figures
