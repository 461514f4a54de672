#include "models/fast_engine/fast_board_engine.h"

#include <algorithm>

namespace cdvp {

void FastBoardEngine::start(const CoordinateStore& store, uint32_t objects) {
    CoordinateWords words{};
    for (uint32_t c = 0; c < kCoordinates; ++c) words[c] = store[c].data();
    engine_.start(objects, words);
    begin_segment();
}

void FastBoardEngine::resume() {
    engine_.resume();
    begin_segment();
}

// The sweep stops at that edge (or where the segment ended before it); the
// buffer keeps what it held then (the board reads only that many entries).
void FastBoardEngine::abort(uint64_t edges) {
    end_edge_ = std::min(edges, end_edge_);
    aborted_ = true;
}

SweepCounters FastBoardEngine::counters_after(uint64_t edges) {
    const BoardObservation seen = engine_.observe(std::min(edges, end_edge_));
    SweepCounters counters;
    counters.cycles = seen.cycles;
    counters.stalls = seen.stalls;
    counters.buffered = seen.buffer_count;
    counters.total_pairs = seen.total_pairs;
    return counters;
}

void FastBoardEngine::begin_segment() {
    end_edge_ = engine_.segment_cycles();
    aborted_ = false;
}

}  // namespace cdvp
