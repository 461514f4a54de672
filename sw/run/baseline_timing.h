// Times the software broad phases on a run's frames: once beside the
// simulation, then again over the same frames with fresh instances for
// --repeat, without simulating them again (the board's times are
// deterministic; the baselines' are what vary from run to run). Each frame
// is timed in the thread's CPU time; a frame disturbed while timed (a
// pre-emption, a move to another CPU) is timed again afterwards, on fresh
// instances stepped through the frames before it, up to run.retime_tries
// times (docs/timing.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "models/common/aabb.h"
#include "sw/baselines/broad_phase.h"
#include "sw/run/frame_source.h"
#include "sw/run/host_factor.h"
#include "sw/run/run_report.h"
#include "sw/timing/rapl_meter.h"
#include "sw/timing/speed_probe.h"
#include "sw/timing/thread_timer.h"
#include "sw/timing/timing_quality.h"

namespace cdvp {

// One call of a baseline on a frame, timed (CPU time, wall time, what
// disturbed it); the pairs it found, sorted, in 'found'. Every baseline
// time cdvp reports, and every reference time cdvp calibrate measures, is
// taken this way.
CallTiming time_find_pairs(BroadPhase& baseline, const std::vector<FloatBox>& boxes, PairList& found);

// The threads a multi-threaded baseline runs on: run.threads when given,
// else as many as this machine and the modelled host (host.cores; 0: not
// stated) both have.
unsigned baseline_threads(uint32_t run_threads, uint32_t host_cores);

class BaselineTimer {
public:
    // names: the baselines (empty: none); host: each baseline's factor to
    // the modelled host; max_tries: how often a disturbed frame is timed
    // again. Throws InputError, under `label` (how the face names the list:
    // "--baseline"), for an unknown name or one given twice.
    BaselineTimer(const std::vector<std::string>& names, HostTiming host, uint32_t max_tries = kDefaultRetimeTries,
                  const std::string& label = "baseline", BaselineOptions options = {});
    BaselineTimer() = default;  // none

    bool empty() const { return names_.empty(); }
    // Each baseline collects at most `budget` pairs a frame (PairBudgetExceeded past it).
    void set_pair_budget(PairBudget budget);
    const std::vector<std::string>& names() const { return names_; }
    uint32_t max_tries() const { return max_tries_; }

    // First run: times each baseline on the frame, checks it finds the
    // board's pairs (sorted) and keeps a digest of them for the later runs.
    std::map<std::string, BaselineTime> time_frame(const std::vector<FloatBox>& boxes, const PairList& board_pairs,
                                                   uint64_t frame);

    // Runs 2 to 'runs': the source rewound and stepped on the pairs the
    // baselines find, which must match the board's of the first run. Each
    // baseline's native times go to totals.baseline_samples(); 'frame_done'
    // is called after each frame (a progress display).
    void repeat(FrameSource& source, uint32_t runs, RunTotals& totals, const std::function<void()>& frame_done);

    // After the runs: each measured frame (after the warm-up) that was
    // disturbed is timed again on fresh instances, in its run's place in
    // totals, until it comes clean or max_tries passes are spent.
    void retime(FrameSource& source, RunTotals& totals);

    // Each baseline's frames timed again: {run, frame, CPU time in ns}.
    const std::map<std::string, std::vector<std::array<double, 3>>>& retimed() const { return retimed_; }

    // Each baseline's timing quality (the loads left for the caller).
    std::map<std::string, TimingQuality> quality(const RunTotals& totals) const;

private:
    // A run's frames that were disturbed and not yet timed clean.
    using Disturbed = std::vector<bool>;
    // A baseline's call with a speed probe before and after it: the slower
    // probe in `probe_ns`.
    CallTiming probed(BroadPhase& baseline, const std::vector<FloatBox>& boxes, PairList& found, double& probe_ns);
    // Marks each measured frame whose probes ran slower than the machine's
    // fast speed (the host profile's, else this run's) as disturbed; the limit.
    double mark_slowed(uint64_t warmup);
    // Fresh instances of the named baselines, holding the run's pair budget.
    std::vector<std::unique_ptr<BroadPhase>> fresh(const std::vector<std::size_t>& which) const;
    // The index of the first measured frame of a run of `frames`.
    static std::size_t first_measured(std::size_t frames, uint64_t warmup) { return frames > warmup ? warmup : 0; }

    std::vector<std::string> names_;
    std::vector<std::unique_ptr<BroadPhase>> first_run_;
    HostTiming host_;
    BaselineOptions options_;
    uint32_t max_tries_ = kDefaultRetimeTries;
    PairBudget budget_;
    std::vector<uint64_t> board_digests_;  // one a frame of the first run
    std::vector<std::vector<Disturbed>> disturbed_;  // [baseline][run][frame]
    std::vector<std::vector<std::vector<float>>> probes_;  // [baseline][run][frame]: the first try's slower probe, ns
    SpeedProbe probe_;
    // This machine's package energy, where RAPL can be read: the last probed call's (< 0: none).
    RaplMeter rapl_;
    double last_energy_j_ = -1;
    double probe_reference_ns_ = 0;  // the fast speed frames were held to
    // By baseline, over measured frames: timed clean by a later try, and the
    // later tries (a frame first disturbed either came clean or never did).
    struct Counts {
        uint64_t retimed = 0, tries = 0, slowed = 0;
    };
    std::vector<Counts> counts_;
    std::map<std::string, std::vector<std::array<double, 3>>> retimed_;
};

}  // namespace cdvp
