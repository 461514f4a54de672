// The answer found from the samples: the fastest configuration at each scene
// and N, held to the fastest software on its host, what bounds it, and the
// crossovers of that envelope on time and on energy.
#include "sw/study/sweep_answer.h"

#include <algorithm>
#include <map>

#include "sw/study/sweep_plots.h"

namespace cdvp::sweep_figures {

namespace {

// A phase's time in the row: its mean over the frames after the warm-up, or
// (a compact row keeps no phase means) its median; 0 when the row has neither.
double row_phase_ns(const RowView& row, const std::string& phase) {
    double ns = number(row, "mean_" + phase + "_ns");
    if (std::isnan(ns)) ns = number(row, "median_" + phase + "_ns");
    return std::isnan(ns) ? 0 : ns;
}

// The frame's parts (AnswerPoint's shares) and the largest of them.
void add_bounds(const Sample& s, AnswerPoint& a) {
    const double bus = row_phase_ns(s.row, "upload") + row_phase_ns(s.row, "start") + row_phase_ns(s.row, "irq") +
                       row_phase_ns(s.row, "readback");
    const double compute = row_phase_ns(s.row, "compute");
    // The cycles the board's address generator waited on a tile load (docs/tiles.md), at its clock.
    const double waits = number(s.row, "median_load_wait_slots");
    const double memory = std::isnan(waits) || !(a.clock_mhz > 0) ? 0 : std::min(compute, waits * 1e3 / a.clock_mhz);
    const double host = row_phase_ns(s.row, "driver");
    const double frame = bus + compute + host;
    if (!(frame > 0)) return;
    a.bus_share = bus / frame;
    a.memory_share = memory / frame;
    a.compute_share = (compute - memory) / frame;
    a.host_share = host / frame;
    const std::pair<double, const char*> parts[] = {
        {a.bus_share, "bus"}, {a.memory_share, "memory"}, {a.compute_share, "compute"}, {a.host_share, "host"}};
    a.bound_by = std::max_element(std::begin(parts), std::end(parts))->second;
}

// The fastest software the point timed, and the board against it.
void add_software(const Sample& s, const std::vector<std::string>& baselines, AnswerPoint& a) {
    for (const std::string& baseline : baselines) {
        const double ns = number(s.row, baseline + "_mean_host_ns");
        if (baseline == "best" || !(ns > 0) || (!a.software.empty() && ns >= a.software_ns)) continue;
        a.software = baseline;
        a.software_ns = ns;
    }
    if (a.software.empty()) return;
    a.software_energy_j = number(s.row, a.software + "_energy_j");
    a.speedup = number(s.row, a.software + "_speedup");
    a.energy_ratio = number(s.row, a.software + "_energy_ratio");
    a.software_timing = text(s.row, a.software + "_timing_quality");
    // The ratio software / board, with the board's own power (its energy but
    // the host's part) and the host's power each at either end of its band:
    // the host's power scales the software's energy and the board's host part alike.
    const double host = number(s.row, "mean_energy_host_j");
    if (std::isnan(host) || !(a.energy_j > 0) || std::isnan(a.software_energy_j)) return;
    const double own = a.energy_j - host;
    auto ratio = [&](double board_factor, double host_factor) {
        return host_factor * a.software_energy_j / (board_factor * own + host_factor * host);
    };
    a.energy_ratio_low = ratio(kBoardPowerBand.high, kHostPowerBand.low);
    a.energy_ratio_high = ratio(kBoardPowerBand.low, kHostPowerBand.high);
}

std::string configuration_words(const Sample& s) {
    std::string words = s.board;
    if (!s.algorithm.empty()) words += " " + s.algorithm;
    words += " m=" + num(s.m);
    if (!s.format.empty()) words += " " + s.format;
    if (!s.setup.empty()) words += " " + s.setup;
    return words;
}

AnswerPoint answer_at(const Sample& fastest, const std::vector<std::string>& baselines) {
    AnswerPoint a;
    a.n = fastest.n;
    a.board = &fastest;
    a.configuration = configuration_words(fastest);
    a.algorithm = fastest.algorithm;
    a.format = fastest.format;
    a.frame_ns = number(fastest.row, "mean_total_ns");
    a.energy_j = number(fastest.row, "mean_energy_j");
    a.clock_mhz = number(fastest.row, "config.clock_mhz");
    a.fmax_mhz = number(fastest.row, "config.resources.timing.fmax_mhz");
    const std::string meets = text(fastest.row, "config.resources.timing.meets_clock");
    a.clock_met = meets == "true" ? "yes" : meets == "false" ? "no" : "";
    add_software(fastest, baselines, a);
    add_bounds(fastest, a);
    return a;
}

// The crossover of one ratio over the scene's N, and what it rests on.
template <class Ratio>
AnswerCrossover crossover_of(const std::vector<AnswerPoint>& points, Ratio ratio) {
    std::vector<std::pair<double, double>> ratios;
    for (const AnswerPoint& a : points) {
        if (ratio(a) > 0) ratios.push_back({a.n, ratio(a)});  // interpolated in its logarithm
    }
    AnswerCrossover c;
    c.at = lasting_crossover(ratios);
    if (c.at.n == 0) return c;
    c.software_timing = "clean";
    c.clock_met = "yes";
    for (const AnswerPoint& a : points) {
        if (std::find(c.at.rests_on.begin(), c.at.rests_on.end(), a.n) == c.at.rests_on.end()) continue;
        if (a.software_timing != "clean") c.software_timing = a.software_timing.empty() ? "unknown" : a.software_timing;
        if (a.clock_met != "yes") c.clock_met = a.clock_met.empty() ? "unknown" : a.clock_met;
    }
    return c;
}

}  // namespace

std::vector<SceneAnswer> find_answers(const Samples& samples, const std::vector<std::string>& baselines) {
    std::vector<std::string> scenes;
    // scene -> N -> the fastest point there (the first in grid order on a tie)
    std::map<std::string, std::map<double, const Sample*>> fastest;
    for (const Sample& s : samples.all) {
        const double frame = number(s.row, "mean_total_ns");
        if (!(frame > 0)) continue;  // a point that timed no frame
        if (std::find(scenes.begin(), scenes.end(), s.scene) == scenes.end()) scenes.push_back(s.scene);
        const Sample*& best = fastest[s.scene][s.n];
        if (best == nullptr || frame < number(best->row, "mean_total_ns")) best = &s;
    }
    std::vector<SceneAnswer> answers;
    for (const std::string& scene : scenes) {
        SceneAnswer answer;
        answer.scene = scene;
        for (const auto& [n, s] : fastest[scene]) answer.points.push_back(answer_at(*s, baselines));
        answer.time = crossover_of(answer.points, [](const AnswerPoint& a) { return a.speedup; });
        answer.energy = crossover_of(answer.points, [](const AnswerPoint& a) { return a.energy_ratio; });
        answer.energy_early = crossover_of(answer.points, [](const AnswerPoint& a) { return a.energy_ratio_high; });
        answer.energy_late = crossover_of(answer.points, [](const AnswerPoint& a) { return a.energy_ratio_low; });
        answers.push_back(answer);
    }
    return answers;
}

void add_answer(const Samples& samples, const std::vector<std::string>& baselines, FigurePlan& plan) {
    const std::vector<SceneAnswer> answers = find_answers(samples, baselines);
    if (answers.empty()) {
        plan.notes.push_back("no answer (answer.md): no point timed a frame (--frames 0)");
        return;
    }
    std::vector<const Sample*> points;
    for (const Sample& s : samples.all) points.push_back(&s);
    std::string context = run_words(points) + ".";
    context[0] = 'B';  // "Board simulated on ..."
    plan.figures.push_back(data_file("answer.csv", answer_csv(answers)));
    plan.figures.push_back(data_file("answer.md", answer_markdown(answers, context)));
    for (Figure& figure : answer_figures(samples, answers)) plan.figures.push_back(std::move(figure));
    plan.answer = answer_summary(answers);
}

}  // namespace cdvp::sweep_figures
