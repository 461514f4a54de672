#include "sw/timing/frame_samples.h"

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
        std::vector<double> samples = run.measured;
        if (figures.includes_warmup) samples = run.warmup;
        if (samples.empty()) continue;
        figures.run_medians.push_back(spread_of(samples).median);
        figures.frames_per_run = samples.size();
        pooled.insert(pooled.end(), samples.begin(), samples.end());
    }
    figures.spread = spread_of(pooled);
    figures.spread.median = spread_of(figures.run_medians).median;
    return figures;
}

}  // namespace cdvp
