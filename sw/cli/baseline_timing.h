// Times the software broad phases on a run's frames: once beside the
// simulation, then again over the same frames with fresh instances for
// --repeat, without simulating them again (the board's times are
// deterministic; the baselines' are what vary from run to run).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "models/common/aabb.h"
#include "sw/baselines/broad_phase.h"
#include "sw/cli/frame_source.h"
#include "sw/cli/host_factor.h"
#include "sw/cli/run_report.h"

namespace cdvp {

// The native wall time of one call of a baseline on a frame, in ns; the
// pairs it found, sorted, in 'found'. Every baseline time cdvp reports, and
// every reference time cdvp calibrate measures, is taken this way.
double time_find_pairs(BroadPhase& baseline, const std::vector<FloatBox>& boxes, PairList& found);

class BaselineTimer {
public:
    // names: --baseline's comma-separated list (empty: none); host: each
    // baseline's factor to the modelled host. Throws InputError for an
    // unknown name or one given twice.
    BaselineTimer(const std::string& names, HostTiming host);
    BaselineTimer() = default;  // none

    bool empty() const { return names_.empty(); }
    // Each baseline collects at most `budget` pairs a frame (PairBudgetExceeded past it).
    void set_pair_budget(PairBudget budget);
    const std::vector<std::string>& names() const { return names_; }

    // First run: times each baseline on the frame, checks it finds the
    // board's pairs (sorted) and keeps a digest of them for the later runs.
    std::map<std::string, BaselineTime> time_frame(const std::vector<FloatBox>& boxes, const PairList& board_pairs,
                                                   uint64_t frame);

    // Runs 2 to 'runs': the source rewound and stepped on the pairs the
    // baselines find, which must match the board's of the first run. Each
    // baseline's native times go to totals.baseline_samples(); 'frame_done'
    // is called after each frame (a progress display).
    void repeat(FrameSource& source, uint32_t runs, RunTotals& totals, const std::function<void()>& frame_done);

private:
    std::vector<std::string> names_;
    std::vector<std::unique_ptr<BroadPhase>> first_run_;
    HostTiming host_;
    PairBudget budget_;
    std::vector<uint64_t> board_digests_;  // one a frame of the first run
};

}  // namespace cdvp
