// The board's results without its clock: what BoardCore computes, event by event.
//
// Assumes: the BoardConfig is valid (validate() passes); `objects` is at most
// the board's capacity (the caller refuses START otherwise, as BoardCore
// does); the coordinate words stay as they were for the whole sweep (the
// board refuses writes while busy); the host reads the whole pair buffer
// before each resume() (as RESUME does on the board).
// Guarantees, for every configuration and any float bit patterns (NaN, -0,
// infinities, denormals, inverted boxes):
//   - pairs(): exactly the pairs BoardCore finds, in its order (first index
//     ascending, then second; on a tiled board block by block first);
//   - observe(e): CYCLES, STALLS, PAIR_COUNT, TOTAL_PAIRS and the phase that
//     BoardCore shows after e step() calls into the current segment (START or
//     RESUME to the next pause or done), back-pressure, end-of-sweep drain
//     and pair-buffer-overflow pauses included; segment_cycles() is the edge
//     at which it pauses or finishes;
//   - buffer_entry(k): BoardCore's pair buffer entry k at any edge of the
//     segment at which PAIR_COUNT > k.
// Cost: O(N + candidates + pairs) time for the pairs (all pairs up to 256 boxes),
// O(hit cycles + pauses) for the timeline; O(N + pairs) memory. No SystemC.
#pragma once

#include <cstdint>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/fast_engine/pair_finder.h"
#include "models/fast_engine/sweep_timeline.h"

namespace cdvp {

class FastEngine {
public:
    // A sweep whose pairs outgrow `budget` throws PairBudgetExceeded at start().
    explicit FastEngine(const BoardConfig& config, PairBudget budget = {});

    const BoardConfig& config() const { return config_; }

    // START over boxes 0..objects-1: finds the pairs and runs to the first
    // pause or done.
    void start(uint32_t objects, const CoordinateWords& words);
    // RESUME after a pause (the host has read the buffer). Throws
    // std::logic_error unless paused.
    void resume();

    uint64_t segment_cycles() const { return timeline_.segment_cycles(); }
    BoardObservation observe(uint64_t edges) const { return timeline_.observe(edges); }
    // At the segment's end: Paused or Done (Idle before the first start).
    SweepState phase() const { return timeline_.phase(); }

    const IndexPair& buffer_entry(uint32_t k) const { return pairs_[timeline_.buffer_begin() + k]; }
    // Every pair of the sweep, in BoardCore's order.
    const PairList& pairs() const { return pairs_; }

private:
    // A tiled board's order: a stable counting sort of the finder's (i, j)
    // order by block, O(pairs + blocks).
    void order_by_block(uint32_t objects);

    BoardConfig config_;
    PairFinder finder_;
    PairList pairs_;
    PairList by_block_;                // scratch of order_by_block
    std::vector<uint64_t> block_ends_;  // scratch: pairs per block, then offsets
    SweepTimeline timeline_;
};

}  // namespace cdvp
