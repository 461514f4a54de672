// The seam between the board's host-visible side (BoardCore: registers,
// coordinate store, status) and what computes a sweep. Two engines implement
// it: the clocked datapath (ClockedEngine, one step per clock edge) and the
// result-oriented fast engine; both give the same pairs in the same order and
// the same counters at every clock edge.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/common/aabb.h"
#include "models/common/pair_budget.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/grid_schedule/grid_slots.h"

namespace cdvp {

// The coordinate memories' contents as the host wrote them: per coordinate
// (Coordinate order), one float32 bit pattern per box.
using CoordinateStore = std::array<std::vector<uint32_t>, kCoordinates>;

// The counters a sweep shows the host, counted from START.
struct SweepCounters {
    uint64_t cycles = 0;       // clock edges
    uint64_t stalls = 0;       // edges the pipeline could not advance
    uint32_t buffered = 0;     // pairs in the pair buffer
    uint64_t total_pairs = 0;  // pairs found (entered the FIFO)
    friend bool operator==(const SweepCounters& a, const SweepCounters& b) {
        return a.cycles == b.cycles && a.stalls == b.stalls && a.buffered == b.buffered &&
               a.total_pairs == b.total_pairs;
    }
};

// Where a sweep stands: the controller's state (the STATUS bits and the
// waveforms' controller_state, in this order) and the clocked datapath's.
enum class SweepState : uint8_t { kIdle, kRunning, kPaused, kDone };

// A sweep runs in segments: from START or RESUME to the next overflow pause
// or to done. The clock does not run between segments. Within a segment the
// engine answers for any edge count, so the host may look at any time.
class BoardEngine {
public:
    virtual ~BoardEngine() = default;
    virtual std::string name() const = 0;

    // START: a sweep over the first `objects` boxes of store (objects <= its
    // depth), with an empty pair buffer. The store stays unchanged until the
    // sweep ends (the board refuses coordinate writes while busy).
    virtual void start(const CoordinateStore& store, uint32_t objects) = 0;
    // RESUME after an overflow pause: the host has read the buffer; it is emptied.
    virtual void resume() = 0;
    // ABORT after `edges` edges of the segment: the sweep stops there and the
    // buffer keeps what it held at that edge.
    virtual void abort(uint64_t edges) = 0;

    // Edges from the segment's first edge until the board pauses or finishes.
    virtual uint64_t segment_edges() = 0;
    // Whether the segment has ended within `edges` edges. Unlike
    // segment_edges(), a clocked engine answers by stepping no further than
    // that edge, so its datapath can be watched edge by edge.
    virtual bool ended_by(uint64_t edges) = 0;
    // Whether the segment ends with the sweep done (else with an overflow pause).
    virtual bool segment_finishes() = 0;
    // The counters after `edges` edges of the segment (edges <= segment_edges()).
    virtual SweepCounters counters_after(uint64_t edges) = 0;
    // Entry k of the pair buffer (board order); after `edges` edges of the
    // segment, entries below counters_after(edges).buffered are valid. The
    // valid entries lie one after another in memory, so the host's burst
    // reads copy them at once.
    virtual const IndexPair& buffer_entry(uint32_t k) = 0;
    // An engine that checks itself against another as it steps (lockstep)
    // names the first difference here, in one line; empty while they agree.
    // It keeps answering as its reference does, so the simulation ends
    // cleanly and the platform reports the difference after the frame.
    virtual std::string divergence() const { return {}; }
    // A grid board's engine: what the sweep started last showed (its grid
    // registers), complete once the sweep is done. Zeros on the seed's board.
    virtual GridSweepStats grid_stats() const { return {}; }
};

// Which engine computes a board's sweeps (models/board/engine_factory.h makes it).
// kRtl: the whole-board RTL under Verilator (models/rtl_engine), the reference;
// kLockstep: the RTL with the clocked engine compared after every edge.
enum class Fidelity : uint8_t { kCycle, kFast, kRtl, kLockstep };
const char* to_string(Fidelity fidelity);

}  // namespace cdvp
