// A frame's simulated time and its phases from closed forms alone: no
// SystemC kernel, no engine stepping. It follows BoardDriver::run_frame
// operation by operation with the BusTiming formulas; only the board's stall
// cycles are estimated (docs/analytic.md says what is exact and measures the rest).
#pragma once

#include <cstdint>
#include <vector>

#include "models/address_generator/tile_config.h"
#include "models/common/aabb.h"
#include "models/common/pair_count.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/board_driver.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/host_port.h"

namespace cdvp {

// What of the board the time depends on: its clock, parallelism and memory
// (as the driver reads them at open) and its pipeline (BoardConfig's
// pipeline_latency() and its collector's FIFO and drain), given by the
// caller so that the driver layer needs no board configuration.
struct AnalyticBoard {
    SimTime period_fs = 0;
    uint32_t m = 1;
    uint32_t pipeline_latency = 0;  // L: a sweep without stalls takes S(N, m) + L edges
    uint32_t fifo_depth = 512;
    uint32_t drain_per_cycle = 1;
    uint32_t buffer_depth = 262144;
    TileConfig tiles;
};

class AnalyticFrame {
public:
    // bus must outlive this. The forms are those of a host that
    // synchronises at every access (PlatformConfig::quantum_ns 0): a host
    // quantum's late notices are not modelled.
    AnalyticFrame(const DriverConfig& driver, const BusTiming& bus, const AnalyticBoard& board);

    // A frame of `objects` boxes whose sweep finds `pairs` pairs, its upload
    // full and its pairs read back as a list.
    FramePhases estimate(uint32_t objects, uint64_t pairs) const;
    // The same for any upload mode and pair format: `changed` boxes differ
    // from the board's copy (all of them when it holds none), and the
    // pairs in board order give each read-back's encoded words.
    FramePhases estimate(uint32_t objects, const PairList& pairs, uint64_t changed) const;
    // The same, counting the pairs first (PairCounter: sort and sweep).
    FramePhases estimate(const std::vector<FloatBox>& boxes);

    // A sweep as the forms see it: the pair buffer's segments (a pause comes
    // when a pair must move into a full buffer, so every segment but the
    // last reads a full buffer back), the estimated stalls (a pause's edge is
    // one) and the cycles. With the pairs in board order, each pause's edge
    // comes from the slot of the pair it waits to move (pause_edges); from a
    // count alone the cycles are spread evenly over the segments.
    struct SweepPlan {
        uint64_t pairs = 0, depth = 1, pauses = 0, stalls = 0, cycles = 0;
        // Edges from START to each pause's edge (the clock stops there), ascending; empty when not known.
        std::vector<uint64_t> pause_edges;
        uint64_t segments() const { return pauses + 1; }
        uint64_t segment_cycles(uint64_t k) const {
            if (!pause_edges.empty()) {
                return (k < pauses ? pause_edges[k] : cycles) - (k == 0 ? 0 : pause_edges[k - 1]);
            }
            return cycles / segments() + (k + 1 == segments() ? cycles % segments() : 0);
        }
        uint64_t segment_pairs(uint64_t k) const { return k < pauses ? depth : pairs - pauses * depth; }
    };
    SweepPlan sweep_plan(uint32_t objects, uint64_t pairs) const;
    // The same, each pause placed by its pair's slot (pairs in board order).
    SweepPlan sweep_plan(uint32_t objects, const PairList& pairs) const;
    // What an upload sends: every box, or (a delta upload, where the bus
    // formula makes it quicker) the `changed` ones as records.
    struct UploadPlan {
        bool delta = false;
        uint64_t sent = 0;  // boxes
        uint64_t bytes() const;
    };
    UploadPlan upload_plan(uint32_t objects, uint64_t changed) const;

    // The address generator's slots: S(N, m), or the tiled schedule's, or
    // the listed schedule's.
    uint64_t sweep_slots(uint32_t objects) const;
    // A grid board's sweeps depend on its boxes (docs/grid_board.md): the
    // caller places the next frame's pairs, pair k (board order) in slot
    // slots[k], and its slots, end_slot; sweep_slots() and sweep_plan() take
    // them until cleared (null). The vector must outlive those calls.
    void set_listed_schedule(const std::vector<uint64_t>* slots, uint64_t end_slot) {
        listed_slots_ = slots;
        listed_end_ = end_slot;
    }
    // Back-pressure stall edges, estimated: none while the drain keeps up
    // with the pairs; past that the drain is busy from the first pair to
    // the last, so the sweep's edges become pairs / drain.
    uint64_t fifo_stall_estimate(uint64_t slots, uint64_t pairs) const;

private:
    friend class AnalyticPipeline;  // times pipelined frames with these forms
    // One programmed access of `words` words (one bus transaction's delay).
    SimTime read_fs(uint64_t words = 1) const;
    SimTime write_fs(uint64_t words = 1) const;
    // From a command's end to the driver noticing an event `event_fs` after
    // it: the interrupt handler running, or the poll whose read finds it
    // (with the driver's back-off).
    SimTime notice_fs(SimTime event_fs, bool by_interrupt) const;
    // The k-th pause between two polls of a wait.
    SimTime poll_gap_fs(uint32_t k) const;
    // The status read after noticing: its own under interrupts, the poll's already.
    SimTime status_read_fs(bool by_interrupt) const { return by_interrupt ? read_fs() : 0; }
    bool board_by_interrupt() const { return driver_.wait == WaitMode::kIrq; }
    bool dma_by_interrupt() const { return board_by_interrupt() && driver_.interrupts == InterruptPolicy::kEvery; }
    // A DMA in register mode, from setting its registers to clearing its status.
    SimTime dma_fs(uint64_t bytes, Direction direction) const;
    // A chain's registers, its bus time, the wait, status and clear.
    SimTime chain_fs(double bus_ns) const;
    SimTime upload_fs(uint32_t objects) const;
    // The full upload's chain on the bus: six descriptors and six arrays.
    double upload_bus_ns(uint32_t objects) const;
    SimTime delta_fs(uint64_t records) const;
    // words_of(k, count): the k-th read-back's words for its `count` pairs.
    template <class Words>
    FramePhases estimate_with(uint32_t objects, const SweepPlan& sweep, const UploadPlan& upload, Words words_of) const;
    static SimTime cpu_fs(double ns) { return ns > 0 ? fs_from_ns(ns) : 0; }

    DriverConfig driver_;
    const BusTiming& bus_;
    AnalyticBoard board_;
    PairCounter counter_;
    const std::vector<uint64_t>* listed_slots_ = nullptr;
    uint64_t listed_end_ = 0;
};

}  // namespace cdvp
