// How far a software timing can be trusted: how many of its frames were
// disturbed (pre-empted or moved to another CPU while timed), how many of
// those a later try timed clean, how many never came clean, how far the
// --repeat runs' means disagree, and the load beside it. Every report,
// sweep row and crossover carries one, so that a figure resting on a
// disturbed timing says so (docs/timing.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cdvp {

// The repeats of a timing agree when their means lie within this of each
// other (max/min - 1): beyond it the runs saw different machines. The first
// run, timed beside the simulator, sits 2-5% above the later ones (sap, dbvt,
// brute and soa at 500 spheres: the simulation cools its caches between
// frames), which is no disturbance; a neighbour that takes a share of the
// caches or the memory bandwidth for a whole run moves it further.
constexpr double kMaxRepeatSpread = 0.10;

// How often a disturbed frame is timed again unless run.retime_tries says otherwise.
constexpr uint32_t kDefaultRetimeTries = 3;

struct TimingQuality {
    uint64_t frames_timed = 0;      // measured frames (after the warm-up) of every run and baseline
    uint64_t frames_disturbed = 0;  // of those, disturbed when first timed
    uint64_t frames_slowed = 0;     // of those, on a machine slower than its fast speed (SpeedProbe)
    uint64_t frames_retimed = 0;    // of those, timed clean by a later try
    uint64_t tries = 0;             // the later tries, all together
    uint64_t never_clean = 0;       // frames still disturbed after the last try
    double repeat_spread = 0;       // max/min - 1 over the runs' means (0 for one run)
    uint32_t runs = 1;
    double probe_ns = 0;  // the machine's fast speed the frames were held to (SpeedProbe), 0: none
    std::array<double, 3> load_start{}, load_end{};

    // Clean: every measured frame came clean and the repeats agree.
    bool clean() const { return never_clean == 0 && !(runs > 1 && repeat_spread > kMaxRepeatSpread); }
    const char* verdict() const { return clean() ? "clean" : "disturbed"; }
    // "clean (3 of 84 frames re-timed, load 0.10 to 0.20)" or
    // "disturbed: 2 of 84 frames never came clean after 3 tries, repeats 7.1% apart (over 5%), load 2.80 to 3.10"
    std::string describe(uint32_t max_tries) const;
    // For a disturbed timing, what would time it clean, in one line
    // ("to time it clean: a quieter machine (load 12.07 on 2 CPUs), --pin-cpu N, --retime-tries 6");
    // empty for a clean one. `pinned`: the run was pinned to a CPU; `cpus`: the CPUs the system runs.
    std::string advice(uint32_t max_tries, bool pinned, uint32_t cpus) const;
    // Two timings side by side (baselines of one run): counts add up, the
    // spread is the worse, the loads the first's.
    TimingQuality& operator+=(const TimingQuality& other);
};

// max/min - 1 over positive means; 0 for fewer than two.
double repeat_spread_of(const std::vector<double>& run_means);

}  // namespace cdvp
