// The fixed workload `cdvp calibrate` times on this machine and every preset
// states its modelled host's times for: the software baselines on the
// spheres scene, seeded, at a few sizes. Its times on two machines give the
// ratio between them (sw/run/host_factor.h); changing it makes every profile
// and every preset's reference timings foreign, so it is versioned.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cdvp::reference_workload {

// 2: sap_mt joined the baselines (on one thread).
constexpr int kVersion = 2;
constexpr const char* kScene = "spheres";
constexpr uint64_t kSeed = 1;
constexpr uint64_t kFrames = 30;
constexpr uint64_t kWarmup = 2;  // the run's default (sw/timing/frame_samples.h)
// Small, the paper's largest, and the 72-point sweep's largest: each weighs
// the same in the geometric mean a baseline's reference time is.
const std::vector<uint64_t>& objects();
// The baselines timed: the five cdvp run had when version 2 was set (sw/baselines).
// The baselines added since (box pruning, the hierarchical grid, FCL's
// managers, ODE's spaces) are not calibrated: they take a profile's overall
// factor, the geometric mean of these five's. The multi-threaded one runs on
// kCalibrationThreads, so that its factor, like the others', is one core's
// speed against the modelled host's; how it scales with threads is this
// machine's (docs/timing.md).
const std::vector<std::string>& baselines();
constexpr unsigned kCalibrationThreads = 1;
// Version 1 timed every baseline but sap_mt: a profile of it still
// calibrates those, and sap_mt takes the profile's overall factor.
constexpr int kFirstVersion = 1;
const std::vector<std::string>& first_version_baselines();

}  // namespace cdvp::reference_workload
