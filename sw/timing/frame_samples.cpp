#include "sw/timing/frame_samples.h"

#include <algorithm>

namespace cdvp {

void FrameSamples::start_run() { runs_.emplace_back(); }

void FrameSamples::add(double value) {
    if (runs_.empty()) start_run();
    Run& run = runs_.back();
    (run.warmup.size() < warmup_ ? run.warmup : run.measured).push_back(value);
}

void FrameSamples::replace(std::size_t run, std::size_t frame, double value) {
    if (run >= runs_.size()) return;
    Run& r = runs_[run];
    if (frame < r.warmup.size()) {
        r.warmup[frame] = value;
    } else if (frame - r.warmup.size() < r.measured.size()) {
        r.measured[frame - r.warmup.size()] = value;
    }
}

std::vector<std::vector<double>> FrameSamples::run_values() const {
    std::vector<std::vector<double>> values;
    for (const Run& run : runs_) {
        std::vector<double>& v = values.emplace_back(run.warmup);
        v.insert(v.end(), run.measured.begin(), run.measured.end());
    }
    return values;
}

TimingFigures FrameSamples::figures() const {
    TimingFigures figures;
    bool any_measured = false;
    for (const Run& run : runs_) any_measured = any_measured || !run.measured.empty();
    figures.includes_warmup = !any_measured && !runs_.empty();
    std::vector<double> pooled;
    for (const Run& run : runs_) {
        const std::vector<double>& samples = figures.includes_warmup ? run.warmup : run.measured;
        if (samples.empty()) continue;
        figures.run_means.push_back(mean_of(samples));
        figures.frames_per_run = samples.size();
        pooled.insert(pooled.end(), samples.begin(), samples.end());
    }
    figures.spread = spread_of(pooled);
    std::vector<double> means = figures.run_means;
    std::sort(means.begin(), means.end());
    figures.spread.mean = quantile(means, 0.5);
    return figures;
}

}  // namespace cdvp
