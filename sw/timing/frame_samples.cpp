#include "sw/timing/frame_samples.h"

#include <algorithm>

namespace cdvp {

void FrameSamples::start_run() { runs_.emplace_back(); }

void FrameSamples::add(double value) {
    if (runs_.empty()) start_run();
    Run& run = runs_.back();
    (run.warmup.size() < warmup_ ? run.warmup : run.measured).push_back(value);
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
