#include "models/board_spec/segment_history.h"

#include <algorithm>

namespace cdvp {

void SegmentHistory::start() {
    at_segment_start_ = SweepCounters{};
    buffered_at_.clear();
    pushed_at_.clear();
    stall_runs_.clear();
}

void SegmentHistory::resume(uint64_t edges) {
    at_segment_start_ = counters_after(edges);
    at_segment_start_.buffered = 0;
    buffered_at_.clear();
    pushed_at_.clear();
    stall_runs_.clear();
}

void SegmentHistory::stall(uint64_t edge) {
    if (!stall_runs_.empty() && stall_runs_.back().first_edge + stall_runs_.back().length == edge) {
        ++stall_runs_.back().length;
        return;
    }
    const uint64_t before = stall_runs_.empty() ? 0 : stall_runs_.back().stalls_before + stall_runs_.back().length;
    stall_runs_.push_back({edge, 1, before});
}

uint64_t SegmentHistory::stalls_through(uint64_t edges) const {
    // The last run that began at or before `edges`.
    auto after = std::upper_bound(stall_runs_.begin(), stall_runs_.end(), edges,
                                  [](uint64_t e, const StallRun& run) { return e < run.first_edge; });
    if (after == stall_runs_.begin()) return 0;
    const StallRun& run = *(after - 1);
    return run.stalls_before + std::min(run.length, edges - run.first_edge + 1);
}

SweepCounters SegmentHistory::counters_after(uint64_t edges) const {
    auto through = [edges](const std::vector<uint64_t>& at) {
        return static_cast<uint64_t>(std::upper_bound(at.begin(), at.end(), edges) - at.begin());
    };
    SweepCounters c = at_segment_start_;
    c.cycles += edges;
    c.stalls += stalls_through(edges);
    c.buffered = static_cast<uint32_t>(through(buffered_at_));
    c.total_pairs += through(pushed_at_);
    return c;
}

}  // namespace cdvp
