// How fast this CPU runs right now, from a few microseconds of fixed work: a
// dependency chain of integer operations and a chase through a buffer in the
// core's L1 cache, both slowed by the core's clock and its sibling
// hyper-thread, neither by what the work before it left in the caches. CPU time leaves out time another task held the
// CPU, but not a CPU slowed by its frequency, a busy sibling or a neighbour
// sharing its caches and memory: on a shared virtual machine these come in
// phases of tens of milliseconds that slow Bullet's sweep and prune by up to
// a fifth. A baseline frame with a probe before and after it that ran slower
// than the machine's fast speed by more than kProbeTolerance was timed on a
// slowed machine, and is timed again (docs/timing.md).
#pragma once

#include <cstdint>
#include <vector>

namespace cdvp {

// Between baseline frames the probe runs 1-3% above its time back to back
// (cdvp calibrate's), with a spread of about 1%; slowed phases run it 7% to
// 40% slower.
constexpr double kProbeTolerance = 0.05;

class SpeedProbe {
public:
    SpeedProbe();
    // One probe: its CPU time in ns.
    double time_ns();

private:
    std::vector<uint32_t> next_;  // a single random cycle through the buffer
    uint32_t at_ = 0;
    uint64_t state_ = 0x9e3779b97f4a7c15ull;
};

// The machine's fast speed from probes: their 10th percentile (0 for none).
double fast_probe_ns(std::vector<double> probes);

}  // namespace cdvp
