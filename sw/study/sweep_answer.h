// A sweep's answer: for each scene and N, the fastest board configuration
// (board, algorithm, m, format and any other axis) by mean frame time, held
// to the fastest software timed at that point, with what bounds its frame,
// and where the board starts to win on time and on energy with how far that
// can be trusted (docs/sweep.md, "The answer"). Written as answer.csv,
// answer.md and two figures, and printed short at the end of a sweep.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "sw/study/sweep_samples.h"

namespace cdvp::sweep_figures {

// The energy model's stated error bands (docs/energy.md, "The presets'
// figures and their error bands"): every figure of the board's own power
// (the device's static and dynamic, the bus's) within x0.5 to x2 of the
// preset's value, the host package's within x0.7 to x2. An energy ratio's
// band takes the board's power at one end and the host's at the other.
struct PowerBand {
    double low, high;
};
constexpr PowerBand kBoardPowerBand{0.5, 2.0};
constexpr PowerBand kHostPowerBand{0.7, 2.0};

// The answer at one scene and N.
struct AnswerPoint {
    double n = 0;
    const Sample* board = nullptr;  // the fastest configuration's point
    std::string configuration;      // "alveo-u250 grid m=8 float32"
    std::string algorithm, format;  // empty when the row does not say
    double frame_ns = NAN, energy_j = NAN;
    // The fastest software on the configuration's own modelled host: the
    // baseline of least mean time a frame among those its point timed.
    std::string software;  // empty: the sweep timed none
    double software_ns = NAN, software_energy_j = NAN;
    double speedup = NAN, energy_ratio = NAN;             // software / board, as the point's row gives them
    double energy_ratio_low = NAN, energy_ratio_high = NAN;  // across the power bands
    std::string software_timing;  // that software's timing quality: clean, disturbed
    // The frame's parts: the bus (upload, start, interrupt, read-back), the
    // board waiting on its memory (tile loads), its compute (the rest of the
    // compute phase) and the host's driver; bound_by names the largest.
    double bus_share = NAN, memory_share = NAN, compute_share = NAN, host_share = NAN;
    std::string bound_by;
    double clock_mhz = NAN, fmax_mhz = NAN;
    std::string clock_met;  // "yes", "no", or "" when the row does not say
};

// Where the board starts to win, and what the crossover rests on.
struct AnswerCrossover {
    Crossover at;
    std::string software_timing;  // of the points it rests on: clean, disturbed, or "" (none)
    std::string clock_met;        // "yes" when every configuration it rests on meets its clock
};

struct SceneAnswer {
    std::string scene;
    std::vector<AnswerPoint> points;  // by N, ascending
    // On time (speedup), and on energy at the model's value and at either
    // end of its band (`energy_early` from the highest ratio, `energy_late`
    // from the lowest), all of the fastest configuration at each N, from
    // which N on it stays ahead through the sweep's largest N.
    AnswerCrossover time, energy, energy_early, energy_late;
};

// The answers of the samples, a scene at a time in the order first met;
// `baselines` as the table's columns name them ("best" is the fastest of
// the others again and is not counted twice).
std::vector<SceneAnswer> find_answers(const Samples& samples, const std::vector<std::string>& baselines);

// answer.csv: a row per scene and N, each scene's crossovers on its rows
// (docs/sweep.md lists the columns).
std::string answer_csv(const std::vector<SceneAnswer>& answers);
// answer.md: a table per scene and a few sentences: the crossovers, what
// they rest on, what bounds the board.
std::string answer_markdown(const std::vector<SceneAnswer>& answers, const std::string& context);
// The short form a sweep prints: a line per scene and N and one for each
// scene's crossovers.
std::string answer_summary(const std::vector<SceneAnswer>& answers);
// "N ~ 142 (interpolated)", "N <= 100 (the sweep's smallest)", "no N of the sweep".
std::string crossover_words(const Crossover& c);
// Where the energy crossover falls with the power bands at either end:
// "from N ~ 120 to N ~ 400 across the power band".
std::string energy_band_words(const SceneAnswer& answer);
// "1.23 mJ", "456 uJ", "2.1 J"
std::string energy_words(double joules);

// answer-time.png and answer-energy.png (one of each per scene, named
// answer-time-SCENE.png, when the sweep ran several).
std::vector<Figure> answer_figures(const Samples& samples, const std::vector<SceneAnswer>& answers);

}  // namespace cdvp::sweep_figures
