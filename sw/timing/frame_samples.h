// Per-frame timings of one quantity over one or more runs of the same frame
// sequence, with each run's warm-up frames left out of the statistics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sw/timing/spread.h"

namespace cdvp {

// Frames left out at the start of every run unless --warmup says otherwise.
// In frame 0 the broad phases allocate and the incremental ones insert every
// proxy (Bullet's btAxisSweep3 took 15-28x its steady cost there at 200 and
// 500 spheres); in frame 1 the first incremental re-sort and the growth of
// its pair cache still cost about twice the steady state. From frame 2 on
// the times sit within the frame-to-frame noise.
constexpr uint64_t kDefaultWarmupFrames = 2;

// A figure that rests on fewer measured frames than this (per run) is
// flagged: below it, p99 is interpolated between the two most extreme
// frames, and one disturbed frame moves the mean by a tenth of its excess.
constexpr uint64_t kMinMeasuredFrames = 10;

// The estimator behind every speedup: each run's mean frame time (a
// simulation pays every frame, the slow ones included: Bullet's dbvt
// rebuilds its tree every few frames at many times its usual cost, and a
// median would land on one side of that or the other), combined over the
// --repeat runs by their median (what varies between runs is the machine,
// and a median is not moved by one disturbed run).
struct TimingFigures {
    // mean: the median over runs of each run's mean (one run: its mean);
    // p50, p99, max: over every measured frame of every run.
    Spread spread;
    std::vector<double> run_means;
    uint64_t frames_per_run = 0;  // measured frames each run's mean rests on
    // True when no frame came after the warm-up: the figures then rest on
    // the warm-up frames themselves rather than on nothing.
    bool includes_warmup = false;

    bool too_few_frames() const { return frames_per_run < kMinMeasuredFrames; }
};

class FrameSamples {
public:
    explicit FrameSamples(uint64_t warmup = kDefaultWarmupFrames) : warmup_(warmup) {}

    // Begins a run of the frame sequence (the first add() begins one too).
    void start_run();
    // The next frame's value in the current run.
    void add(double value);

    // Replaces frame `frame` (counted from the run's first, warm-up included)
    // of run `run` (from 0): a frame timed again. Out of range: nothing.
    void replace(std::size_t run, std::size_t frame, double value);

    // Every run's values in frame order, warm-up frames first.
    std::vector<std::vector<double>> run_values() const;

    uint64_t runs() const { return runs_.size(); }
    uint64_t warmup() const { return warmup_; }
    TimingFigures figures() const;

private:
    struct Run {
        std::vector<double> warmup;    // the first 'warmup_' frames
        std::vector<double> measured;  // every frame after them
    };
    uint64_t warmup_;
    std::vector<Run> runs_;
};

}  // namespace cdvp
