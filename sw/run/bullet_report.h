// What only Bullet has in `cdvp bullet`'s report and summary, beside the run
// report of the board's frames (sw/run/run_report.h): per frame, the software
// world's broad-phase and step times, the host's bookkeeping around the
// board in the board's world, the broad phase's share of the step, its
// Amdahl bound and the gains the board gives; over the frames after the
// warm-up, each time's mean (for the software world, the median of the
// --repeat runs' means), p50, p99 and maximum, and the ratios of the means.
// Times name their clock (docs/timing.md): _host_ns is native time (the
// thread's CPU time) x the host factor, a plain _ns simulated.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/bullet/scenes.h"
#include "sw/timing/frame_samples.h"
#include "sw/timing/timing_quality.h"

namespace cdvp {

struct BulletFrame {
    uint64_t frame = 0;
    uint32_t proxies = 0;
    std::size_t pairs = 0;           // the board's pairs
    std::size_t contacts = 0;        // contact points in the board's world
    double board_ns = 0;             // the board's frame, simulated (the run report's total_ns)
    double bookkeeping_host_ns = 0;  // the host around it: AABB update and pair-cache upkeep
    double software_broadphase_host_ns = 0;  // Bullet's broad phase: AABB update and pair search
    double software_step_host_ns = 0;        // Bullet's whole step on that broad phase

    double share() const;
    // Amdahl: a broad phase that cost nothing would speed the step up at most this much.
    double amdahl_bound() const;
    // Bullet's broad phase over the board and the host's work around it.
    double broadphase_speedup() const;
    // The step over the step with the board in place of Bullet's broad phase.
    double step_speedup() const;
};

class BulletTimes {
public:
    explicit BulletTimes(uint64_t warmup_frames);

    // A frame of the first run: the board's world and the software world
    // stepped in lockstep.
    void add(const BulletFrame& frame);
    // A later run of the software world alone (--repeat), from the scene's
    // start, and its frames' times.
    void start_software_run();
    void add_software(double broadphase_host_ns, double step_host_ns);
    // A software frame timed again (a disturbed one): frame `frame` of run `run`, from 0.
    void replace_software(std::size_t run, std::size_t frame, double broadphase_host_ns, double step_host_ns);
    // What the software world's timing can be trusted for, the tries it
    // had, and whether it ran pinned to a CPU.
    void set_quality(const TimingQuality& quality, uint32_t tries, bool pinned);
    const TimingQuality& quality() const { return quality_; }

    const std::vector<BulletFrame>& frames() const { return frames_; }
    uint64_t warmup_frames() const { return warmup_frames_; }
    // Each time over the frames after the warm-up.
    TimingFigures figures(double BulletFrame::*time) const;
    // A frame of the figures' means: its ratios are the gains of the means.
    BulletFrame means() const;

    // The report's "bullet" section: the scene, the software, every frame
    // and the summary.
    nlohmann::json section(const SceneSpec& spec, BroadphaseKind software) const;
    // The summary's table: the first frames, then the mean, p50, p99 and
    // maximum of each time. has_report: --report lists every frame.
    std::string table(BroadphaseKind software, const std::string& host, const std::string& factor,
                      bool has_report) const;

private:
    uint64_t warmup_frames_;
    FrameSamples board_, bookkeeping_, broadphase_, step_;
    std::vector<BulletFrame> frames_;
    TimingQuality quality_;
    uint32_t tries_ = 0;
    bool pinned_ = false;
};

}  // namespace cdvp
