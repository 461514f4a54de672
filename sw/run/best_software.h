// "best" among a run's baselines: the software an expert would pick for the
// scene, timed candidate by candidate, the fastest of them named in the
// report, and the board's speedup and energy ratio against it
// (docs/baselines.md). A run names the fastest baseline it timed whether or
// not "best" was asked for.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sw/run/report_summary.h"

namespace cdvp {

constexpr const char* kBestSoftware = "best";

// Box pruning's sweep grows as N^(5/3) on a spread scene, but it stays the
// fastest on heavy-tailed sizes up to 100,000 boxes (docs/baselines.md);
// from this many boxes on it would take seconds a frame, so it is left out
// of "best" (keeping the software at 10^6 boxes near a second a frame).
constexpr std::size_t kPruneCandidateLimit = 500000;

// What "best" stands for at `objects` boxes a frame (none: not known yet,
// every candidate) on `threads` threads: box pruning and the hierarchical
// grid, on one thread and, with more than one, on all of them.
std::vector<std::string> best_candidates(std::optional<std::size_t> objects, unsigned threads);

// The baselines a run times: `names` with "best" replaced by the candidates
// that are not named on their own.
std::vector<std::string> resolve_baselines(const std::vector<std::string>& names, std::optional<std::size_t> objects,
                                           unsigned threads);
bool asks_for_best(const std::vector<std::string>& names);

// The baseline with the least mean frame time on the modelled host among
// those that timed a frame; none when no baseline did.
std::optional<std::string> fastest_baseline(const ReportSummary& summary);

}  // namespace cdvp
