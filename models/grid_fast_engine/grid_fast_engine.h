// The grid board's results without its clock: GridSearch's pairs and slots,
// replayed through the pair FIFO and buffer by SweepTimeline. As FastEngine
// is to the seed's board: every register after any edge of a segment, the
// pair buffer at every pause and at done.
//
// Assumes what FastEngine assumes (a valid config with algorithm kGrid,
// objects within the capacity, words unchanged during the sweep, the buffer
// read before each resume). Guarantees, for any words (NaN, infinities, -0,
// denormals, inverted boxes): pairs() are exactly the pairs the seed's board
// finds in the same format, each once, in the grid board's order
// (docs/grid_board.md); observe(e) is what the clocked grid board shows
// after e edges of the segment. Cost: O(N x cells a box + tests in the busy
// cells + N x large boxes) time, O(N + entries + pairs) memory.
#pragma once

#include <cstdint>
#include <vector>

#include "models/fast_engine/sweep_timeline.h"
#include "models/grid_fast_engine/grid_search.h"

namespace cdvp {

class GridFastEngine {
public:
    explicit GridFastEngine(const BoardConfig& config, PairBudget budget = {})
        : search_(config, budget), timeline_(config) {}

    void start(uint32_t objects, const CoordinateWords& words) {
        const uint64_t end = search_.run(objects, words, pairs_, slots_);
        timeline_.start_listed(pairs_, slots_, end);
    }
    void resume() { timeline_.resume(); }

    uint64_t segment_cycles() const { return timeline_.segment_cycles(); }
    BoardObservation observe(uint64_t edges) const { return timeline_.observe(edges); }
    SweepState phase() const { return timeline_.phase(); }
    const IndexPair& buffer_entry(uint32_t k) const { return pairs_[timeline_.buffer_begin() + k]; }

    const PairList& pairs() const { return pairs_; }
    // The slot each pair is compared in (pairs() order).
    const std::vector<uint64_t>& slots() const { return slots_; }
    const GridSweepStats& stats() const { return search_.stats(); }

private:
    GridSearch search_;
    PairList pairs_;
    std::vector<uint64_t> slots_;
    SweepTimeline timeline_;
};

}  // namespace cdvp
