// The driver's sequence (driver_sequence.h) evaluated in closed form: no
// SystemC kernel, no engine stepping, no host memory. Each register access,
// transfer and wait takes its time from the BusTiming formulas (one PIO
// access of w words is one delay of w x R or w x W, rounded to femtoseconds
// as the platform rounds it; a DMA's whole time is one wait), and the board
// and its DMA engine answer from the sweep's plan: a segment of the sweep
// ends its cycles x P after its START or RESUME, STATUS and the counters
// read what the board would show then. The interrupt line follows the
// platform's: the board's and the DMA's requests ORed, a rising edge
// notifying the host one interrupt lag later unless a notification is still
// on its way; polls jump to the one that sees their event. AnalyticFrame and
// AnalyticPipeline run the driver's frames on it (docs/analytic.md).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "models/address_generator/tile_config.h"
#include "models/common/aabb.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/driver_sequence.h"
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

// A sweep as the forms see it: the pair buffer's segments (a pause comes
// when a pair must move into a full buffer, so every segment but the last
// reads a full buffer back), the estimated stalls (a pause's edge is one)
// and the cycles. With the pairs in board order, each pause's edge comes
// from the slot of the pair it waits to move (pause_edges); from a count
// alone the cycles are spread evenly over the segments.
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

// A frame as the closed forms see it.
struct FramePlan {
    uint32_t objects = 0;
    uint64_t changed = 0;  // boxes whose words differ from their bank's copy (all when it holds none)
    SweepPlan sweep;
    // The pairs in board order: each read-back's words in the pair format.
    // Null: each read-back moves two words a pair.
    const IndexPair* pairs = nullptr;
};

class ClosedForm {
public:
    // Each frame's plan stands for its boxes and pairs (it outlives the
    // frame's read-back): nothing is moved.
    using Frame = FramePlan;
    struct Pairs {
        void clear() {}
        void swap(Pairs&) {}
    };
    // A phase is summed in femtoseconds, exact, and converted once.
    using Time = SimTime;
    static Time span(SimTime fs) { return fs; }
    static double ns(Time fs) { return ns_from_fs(fs); }

    // bus must outlive this.
    ClosedForm(const DriverConfig& driver, const BusTiming& bus, const AnalyticBoard& board);

    // One programmed access of `words` words (one bus transaction's delay).
    SimTime read_fs(uint64_t words = 1) const;
    SimTime write_fs(uint64_t words = 1) const;
    // From a command's end to the poll whose read first sees an event
    // `event_fs` after it (with the driver's back-off).
    SimTime poll_notice_fs(SimTime event_fs) const;
    // The full upload's chain on the bus: six descriptors and six arrays, in the bridge's order.
    double upload_bus_ns(uint32_t objects) const;

    // The sequence's operations.
    SimTime now() const { return now_; }
    uint32_t read(uint64_t address);
    void write(uint64_t address, uint32_t value);
    void pio_write(uint64_t, uint64_t, uint32_t bytes) { now_ += write_fs(bytes / 4); }
    void pio_read(uint64_t, uint64_t, uint32_t bytes) { now_ += read_fs(bytes / 4); }
    void cpu(double ns) {
        if (ns > 0) now_ += fs_from_ns(ns);
    }
    // Nothing here times out: no deadlines.
    template <class Worst>
    SimTime timeout(Worst) const {
        return 0;
    }
    SimTime deadline_after(SimTime) const { return kNever; }
    void wait_for_interrupt(SimTime timeout, uint64_t awaited);
    void wait_for_interrupt_since(SimTime since, SimTime timeout, uint64_t awaited);
    uint32_t poll(uint64_t address, uint32_t bits, SimTime deadline);
    uint64_t memory_size() const { return std::numeric_limits<uint64_t>::max(); }
    const BusTiming& bus() const { return bus_; }

    // The frame's data: its plan.
    uint32_t objects(const Frame& frame) const { return frame.objects; }
    void stage(const Frame& frame) { staged_ = &frame; }
    uint64_t changed_boxes(const Frame& frame) const { return frame.changed; }
    void keep_bank() {}
    void stage_delta_records() {}
    uint64_t stage_chain(Chain chain, uint64_t count);
    uint64_t host_address(HostArea, uint32_t = 0) const { return 0; }
    bool pair_area_holds(uint64_t) const { return true; }
    void take_pairs(Pairs&, uint64_t, uint32_t, uint32_t) {}
    void banks_swapped() {}

private:
    static constexpr SimTime kNever = std::numeric_limits<SimTime>::max();
    // The interrupt line: the board's and the DMA's requests, the
    // notification on its way to the host, the last one that came.
    struct Line {
        SimTime board_at = kNever, dma_at = kNever;  // requests yet to rise
        bool board_high = false, dma_high = false;
        SimTime pending = kNever, fired = kNever, taken = kNever;
    };

    // What the register holds now; when the status at `address` shows its event.
    uint32_t value(uint64_t address) const;
    SimTime event_at(uint64_t address) const;
    // The frame whose pair buffer PAIR_BANK shows, and its segment.
    const FramePlan* shown(uint64_t& segment) const;
    void start_segment(SimTime at);
    // The line's events up to `t`, in time order (a notification due at the
    // same time as a rise comes first).
    void advance(SimTime t);
    void rise(bool board, SimTime at);
    // The time the next notification reaches a host waiting from `t`; kNever
    // when none will.
    SimTime next_notification(SimTime t);
    // HostPort::wait_for_interrupt_since: at once for a notification since
    // `since` not taken yet, else the next one.
    SimTime notification_since(SimTime since, SimTime t);
    // Waiting ends at `t`, or (no notification comes) where the timeout's
    // look finds the awaited event.
    void woken(SimTime t, uint64_t awaited);

    const DriverConfig& driver_;
    const BusTiming& bus_;
    AnalyticBoard board_;
    SimTime read_, write_, lag_;
    SimTime now_ = 0;
    Line line_;
    // The board: the frame in the host's bank, the one it sweeps (its
    // segment, when that ends, the cycles by then), the one before.
    const FramePlan* staged_ = nullptr;
    const FramePlan* sweeping_ = nullptr;
    const FramePlan* previous_ = nullptr;
    uint64_t segment_ = 0;
    SimTime segment_end_ = kNever;
    uint64_t cycles_ = 0;
    uint32_t pair_bank_ = 0;
    // The DMA engine: the length set, the chain staged, when the transfer ends.
    uint32_t bytes_ = 0;
    double chain_ns_ = 0;
    SimTime dma_end_ = kNever;
};

}  // namespace cdvp
