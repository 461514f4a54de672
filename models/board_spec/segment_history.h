// What a segment showed the host, edge by edge, for an engine that steps the
// clock: the edge (1-based, within the segment) at which each pair entered
// the pair buffer and the FIFO, and each run of stall edges. An engine may
// step a segment ahead in bulk and still answer counters_after() for any
// earlier edge from it.
#pragma once

#include <cstdint>
#include <vector>

#include "models/board_spec/board_engine.h"

namespace cdvp {

class SegmentHistory {
public:
    // START: counters from zero.
    void start();
    // RESUME: the next segment carries on from the counters after `edges`
    // edges of this one, with an empty pair buffer.
    void resume(uint64_t edges);

    // At edge `edge` of the segment (edges counted from 1, in order).
    void stall(uint64_t edge);
    void buffered(uint64_t edge, uint64_t pairs = 1) { buffered_at_.insert(buffered_at_.end(), pairs, edge); }
    void pushed(uint64_t edge, uint64_t pairs) { pushed_at_.insert(pushed_at_.end(), pairs, edge); }

    // The counters after `edges` edges of the segment (edges at or below the
    // last one recorded).
    SweepCounters counters_after(uint64_t edges) const;

private:
    uint64_t stalls_through(uint64_t edges) const;

    SweepCounters at_segment_start_;
    std::vector<uint64_t> buffered_at_;
    std::vector<uint64_t> pushed_at_;
    struct StallRun {
        uint64_t first_edge;
        uint64_t length;
        uint64_t stalls_before;  // stall edges of the segment before this run
    };
    std::vector<StallRun> stall_runs_;
};

}  // namespace cdvp
