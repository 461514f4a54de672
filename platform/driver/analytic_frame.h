// A frame's simulated time and its phases from closed forms alone: no
// SystemC kernel, no engine stepping. The driver's own sequence of
// operations (driver_sequence.h, BoardDriver::run_frame's) runs on the
// closed-form executor (closed_form.h), each operation priced by the
// BusTiming formulas; what is planned here is the sweep: its segments,
// cycles and stalls. Only the board's stall cycles are estimated
// (docs/analytic.md says what is exact and measures the rest).
#pragma once

#include <cstdint>
#include <vector>

#include "models/address_generator/tile_config.h"
#include "models/common/aabb.h"
#include "models/common/pair_count.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/closed_form.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/frame_phases.h"
#include "platform/driver/host_port.h"

namespace cdvp {

class AnalyticFrame {
public:
    using SweepPlan = cdvp::SweepPlan;

    // bus must outlive this. The forms are those of a host that
    // synchronises at every access (PlatformConfig::quantum_ns 0): a host
    // quantum's late notices are not modelled.
    AnalyticFrame(const DriverConfig& driver, const BusTiming& bus, const AnalyticBoard& board);

    // A frame of `objects` boxes whose sweep finds `pairs` pairs, its upload
    // full and each read-back moving two words a pair.
    FramePhases estimate(uint32_t objects, uint64_t pairs) const;
    // The same for any upload mode and pair format: `changed` boxes differ
    // from the board's copy (all of them when it holds none), and the
    // pairs in board order give each read-back's encoded words.
    FramePhases estimate(uint32_t objects, const PairList& pairs, uint64_t changed) const;
    // The same, counting the pairs first (PairCounter: sort and sweep).
    FramePhases estimate(const std::vector<FloatBox>& boxes);

    // The sweep's plan from a pair count (the cycles spread evenly over the
    // segments), or with each pause placed by its pair's slot (pairs in board order).
    SweepPlan sweep_plan(uint32_t objects, uint64_t pairs) const;
    SweepPlan sweep_plan(uint32_t objects, const PairList& pairs) const;

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

    const DriverConfig& driver() const { return driver_; }
    const BusTiming& bus() const { return bus_; }
    const AnalyticBoard& board() const { return board_; }

private:
    // The driver's single frame on the closed forms.
    FramePhases run(const DriverConfig& driver, const FramePlan& plan) const;

    DriverConfig driver_;
    DriverConfig full_upload_;  // the driver's, uploading every box: a count says nothing of changes
    const BusTiming& bus_;
    AnalyticBoard board_;
    PairCounter counter_;
    const std::vector<uint64_t>* listed_slots_ = nullptr;
    uint64_t listed_end_ = 0;
};

}  // namespace cdvp
