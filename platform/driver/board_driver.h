// The host driver of the collision board: host software that reaches the
// board over the PCI bus and stages data in host RAM, all through a HostPort.
// Its frames are the driver's sequence (driver_sequence.h) performed through
// the port (port_executor.h); the analytic level evaluates the same sequence
// in closed form (closed_form.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "models/common/aabb.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/number_format/number_format.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/driver_sequence.h"
#include "platform/driver/frame_phases.h"
#include "platform/driver/frame_time.h"
#include "platform/driver/host_port.h"
#include "platform/driver/port_executor.h"

namespace cdvp {

class BoardDriver {
public:
    // port: the host the driver runs on; period_fs: the board's clock period;
    // bus: the timing the timeouts are derived from.
    BoardDriver(HostPort& port, SimTime period_fs, const DriverConfig& config, std::shared_ptr<const BusTiming> bus);

    // Host RAM the driver needs for a board of this capacity and pair buffer
    // (the pair area for config's pair format, the delta records' area when
    // it may upload deltas).
    static uint64_t host_memory_bytes(uint32_t capacity, uint32_t buffer_depth, const DriverConfig& config = {});

    // Checks the board's identity and reads its capacity and number format.
    void open();
    uint32_t capacity() const { return executor_.capacity(); }
    // The board's comparators' format (its FORMAT register): the driver
    // writes boxes in it (platform/driver/quantiser.h).
    NumberFormat format() const { return executor_.format(); }

    // One frame: every overlapping pair into pairs (board order), or an
    // exception (DeviceFault when the simulated system faulted,
    // PairBudgetExceeded when the pairs outgrow the budget) and no pairs;
    // after a fault the driver aborts the DMA engine and the board, so the
    // next frame starts clean.
    FramePhases run_frame(const std::vector<FloatBox>& boxes, PairList& pairs);

    // Frames pipelined, on a board with two box banks (BOX_BANKS = 2): two
    // frames in flight. submit() uploads `boxes` into the host's bank while
    // the board sweeps the frame before, waits for that frame's end, starts
    // the new frame and reads the finished frame's pairs back during the new
    // sweep: it returns true with them (pairs, *phases) when a frame
    // finished, false on the first call. finish() completes the frame in
    // flight the same way (false when none is). Faults are run_frame's; after
    // one no frame is in flight.
    bool pipelined() const { return sequence_.pipelined(); }
    bool submit(const std::vector<FloatBox>& boxes, PairList& pairs, FramePhases& phases);
    bool finish(PairList& pairs, FramePhases& phases);

private:
    // Refuses a frame of more boxes than the board holds (invalid_argument).
    void check_capacity(const std::vector<FloatBox>& boxes) const;
    // Fails with what recover() leaves: no pairs, no frame in flight.
    void fail_frames(PairList& pairs);
    // Stops the DMA engine and the board and clears their status (best effort).
    void recover();

    HostPort& port_;
    DriverConfig config_;
    PortExecutor executor_;
    DriverSequence<PortExecutor> sequence_;
};

}  // namespace cdvp
