// The board's clock-edge timeline of one sweep, computed from its pairs alone.
#pragma once

#include <cstdint>
#include <vector>

#include "models/address_generator/sweep_schedule.h"
#include "models/board_spec/board_config.h"
#include "models/board_spec/board_engine.h"

namespace cdvp {

// Registers as BoardCore would show them after a number of step() calls.
struct BoardObservation {
    uint64_t cycles = 0;        // CYCLES
    uint64_t stalls = 0;        // STALLS
    uint32_t buffer_count = 0;  // PAIR_COUNT: pairs in the pair buffer
    uint64_t total_pairs = 0;   // TOTAL_PAIRS: pairs that entered the FIFO
    uint32_t fifo_level = 0;    // pairs in the FIFO (not a register; for tests and tracing)
    SweepState phase = SweepState::kRunning;
};

// Replays BoardCore's pipeline, FIFO and pair buffer without stepping empty
// edges. Only the pairs matter: a pair (i, j) of an N-box sweep leaves the
// address generator's slot
//     c(i, j) = S(N) - S(N - i) + (j - i - 1) / (2m - 1)
// (row i starts after the rows before it; each cycle covers 2m-1 columns; on
// a tiled board SweepSchedule::pair_slot, whose slots include the bubbles
// spent waiting for tiles) and
// reaches the collector at the (c + 1 + D)-th edge that advances the pipeline,
// D = block RAM + compare stages; the end marker is slot S(N). Between two
// such events every edge only drains min(drain, fifo, room) pairs, so a run of
// k alike edges is one step of arithmetic:
//   - advance edges (empty slots) cost no stall;
//   - back-pressure edges (the FIFO lacks room for the head slot's hits) and
//     the end-of-sweep drain edges cost one stall each;
//   - an edge that finds a pair to move and the buffer full pauses the board
//     (a stall); RESUME empties the buffer.
// Work is O(hit slots + pauses) per sweep; a segment whose pairs all fit in
// the buffer's room cannot pause and runs without the buffer's checks, and
// from listed slots that never meet back-pressure it is one pass over the
// slots (the FIFO's level in closed form). Each segment (START or RESUME to the
// next pause or done) keeps a cursor every kCheckpointEvery events, so
// observe() replays at most that many events.
class SweepTimeline {
public:
    explicit SweepTimeline(const BoardConfig& config);

    // A sweep of `objects` boxes whose pairs, in BoardCore's order (the
    // schedule's: by block, then first ascending, then second ascending;
    // first < second < objects), are `pairs`.
    // The vector must outlive the sweep and stay unchanged. Runs the first
    // segment.
    void start(uint32_t objects, const std::vector<IndexPair>& pairs);
    // A sweep whose schedule the caller has placed (the grid board's): pair
    // k leaves the front end in slot slots[k] (non-decreasing; pairs of one
    // slot are that slot's lane hits) and the end marker in end_slot. Both
    // vectors must outlive the sweep and stay unchanged.
    void start_listed(const std::vector<IndexPair>& pairs, const std::vector<uint64_t>& slots, uint64_t end_slot);
    // The host read the full buffer: runs the next segment. Only while paused.
    void resume();

    // Edges from the segment's start to the edge that paused or finished it.
    uint64_t segment_cycles() const { return end_.segment_edges; }
    // The registers after `edges` step() calls into the segment (edges past
    // the segment's end observe its end: the clock has stopped).
    BoardObservation observe(uint64_t edges) const;
    // Phase at the segment's end: Paused or Done (Idle before any start).
    SweepState phase() const { return end_.phase; }
    // Index in the pair list of the first pair in the buffer this segment.
    uint64_t buffer_begin() const { return buffer_begin_; }

    static constexpr uint32_t kCheckpointEvery = 16;

private:
    // The slot the pipeline delivers next that carries hits (or the end marker).
    struct HeadSlot {
        uint64_t slot = 0;
        uint32_t hits = 0;  // 0 for the end marker
        bool known = false;
    };
    // Everything that determines the following edges.
    struct Cursor {
        uint64_t segment_edges = 0;
        uint64_t cycles = 0;
        uint64_t stalls = 0;
        uint64_t advances = 0;   // edges that moved the pipeline, bubbles included
        uint64_t total = 0;
        uint64_t next_pair = 0;  // first pair not yet pushed into the FIFO
        uint32_t fifo = 0;
        uint32_t buffer = 0;
        bool end_seen = false;
        SweepState phase = SweepState::kIdle;
        HeadSlot head;  // the slot of next_pair, once computed
    };

    // Sets cursor.head to the slot of cursor.next_pair and its hits.
    void locate_head(Cursor& cursor) const;
    // The same on a tiled board or from listed slots (out of the untiled path).
    void locate_tiled_head(Cursor& cursor) const;
    // Runs edges until the segment ends or `limit` edges into it; with
    // checkpoints, records a cursor every kCheckpointEvery events.
    void run(Cursor& cursor, uint64_t limit, std::vector<Cursor>* checkpoints) const;
    // k edges that each drain: advance edges (stall_per_edge 0) or stall edges (1).
    void drain_edges(Cursor& cursor, uint64_t k, uint32_t stall_per_edge) const;
    // Whether a segment from `start` can never pause: the pairs still to
    // come and those in the FIFO fit in the buffer's room.
    bool cannot_pause(const Cursor& start) const;
    // run() to the segment's end for a segment that cannot pause: the buffer
    // never limits a drain, so each hit slot is a few lines of arithmetic
    // (the same edges, stalls and levels), with a checkpoint every
    // kCheckpointEvery hit slots.
    void run_unpaused(Cursor& cursor, std::vector<Cursor>& checkpoints) const;
    // The same from listed slots, when no slot meets back-pressure either:
    // then the FIFO after each pair's edge is max(f - drain x (slots since
    // the last pair's), 0) + 1, one branch-free pass over the slots, and
    // the segment's end follows in closed form. False (the cursor and the
    // checkpoints as they were) when a slot would meet back-pressure.
    bool run_listed_unstalled(Cursor& cursor, std::vector<Cursor>& checkpoints) const;
    // Runs from `start` to the segment's end, keeping checkpoints.
    void run_segment(const Cursor& start);
    // The first segment of a sweep whose pairs and slots are set.
    void begin();

    uint32_t lanes_;
    uint64_t line_delay_;  // D: edges from issue to the collector
    uint32_t fifo_depth_;
    uint32_t drain_per_cycle_;
    uint32_t buffer_depth_;
    uint32_t m_;
    TileConfig tiles_;
    SweepSchedule schedule_;  // tiled boards only

    uint32_t objects_ = 0;
    uint64_t sweep_cycles_ = 0;  // S(N, m): the end marker's slot
    const std::vector<IndexPair>* pairs_ = nullptr;
    const std::vector<uint64_t>* listed_slots_ = nullptr;  // start_listed's
    uint64_t buffer_begin_ = 0;
    std::vector<Cursor> checkpoints_;  // [0] is the segment's start
    Cursor end_;
};

}  // namespace cdvp
