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
// buffer keeps what it held then.
void FastBoardEngine::abort(uint64_t edges) {
    end_edge_ = std::min(edges, end_edge_);
    buffer_.resize(engine_.observe(end_edge_).buffer_count);
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
    const uint32_t buffered = engine_.observe(end_edge_).buffer_count;
    buffer_.clear();
    for (uint32_t k = 0; k < buffered; ++k) buffer_.push_back(engine_.buffer_entry(k));
}

}  // namespace cdvp
