// The host driver of the collision board: host software that reaches the
// board over the PCI bus and stages data in host RAM, all through a HostPort.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/common/aabb.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/number_format/number_format.h"
#include "models/pci/bus_timing.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/frame_time.h"
#include "platform/driver/host_port.h"

namespace cdvp {

// The simulated system faulted (a DMA or bus fault, a board error status, a
// driver timeout): the input was fine. The frame produced no pairs.
class DeviceFault : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A wait's deadline would pass kSimulatedTimeLimit (platform/driver/frame_time.h):
// refused before the wait starts. cdvp run's estimate before any work holds
// a whole run to the same limit, so a run it lets through never meets this.
class SimulatedTimeLimit : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Where a frame's simulated time went; the phases add up to total_ns.
struct FramePhases {
    double upload_ns = 0;    // staging boxes on the board (one DMA chain or PIO, with set-up and completion)
    double start_ns = 0;     // writing the object count and START
    double compute_ns = 0;   // the board's clock running (cycles x period)
    double irq_ns = 0;       // from the board's interrupt to the driver noticing (interrupt or polling)
    double readback_ns = 0;  // status reads, pair transfers, RESUME after overflows
    double driver_ns = 0;    // host CPU work: packing boxes, unpacking pairs, driver calls
    double total_ns = 0;
    uint64_t compute_cycles = 0;
    uint64_t stall_cycles = 0;
    // What moved over the bus: the boxes uploaded (all of them, or the
    // changed ones of a delta upload), their bytes, and the pair words' bytes.
    uint32_t boxes_sent = 0;
    uint64_t upload_bytes = 0;
    uint64_t readback_bytes = 0;
    uint32_t overflow_pauses = 0;
    uint32_t timeouts_recovered = 0;  // waits whose interrupt never came, finished by polling STATUS
};

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
    uint32_t capacity() const { return capacity_; }
    // The board's comparators' format (its FORMAT register): the driver
    // writes boxes in it (platform/driver/quantiser.h).
    NumberFormat format() const { return format_; }

    // One frame: every overlapping pair into pairs (board order), or an
    // exception (DeviceFault when the simulated system faulted,
    // PairBudgetExceeded when the pairs outgrow the budget) and no pairs;
    // after a fault the driver aborts the DMA engine and the board, so the
    // next frame starts clean.
    FramePhases run_frame(const std::vector<FloatBox>& boxes, PairList& pairs);

private:
    enum Phase { kUpload, kStart, kCompute, kIrq, kReadback, kDriver, kPhases };
    void charge(Phase phase);  // the time since the last charge goes to phase
    void cpu_work(double ns);  // host CPU time, charged to the driver
    // The pause after the polls-th poll of a wait (back-off).
    void poll_pause(uint32_t polls);

    uint32_t read(uint64_t address);
    void write(uint64_t address, uint32_t value);
    void pio_read(uint64_t address, void* data, uint32_t length);
    void pio_write(uint64_t address, const void* data, uint32_t length);
    FramePhases frame(const std::vector<FloatBox>& boxes, PairList& pairs);
    // Stops the DMA engine and the board and clears their status (best effort).
    void recover();
    // How long a wait whose worst case is worst_ns may take (FrameTime);
    // throws SimulatedTimeLimit for a deadline past kSimulatedTimeLimit.
    SimTime timeout_for(double worst_ns) const;
    // Waits for the interrupt or a poll to find any of bits in the register's
    // value, until the timeout; returns the value. what names the wait.
    // by_interrupt: wait for the interrupt (else poll).
    uint32_t wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what, bool by_interrupt);
    bool dma_by_interrupt() const;
    void run_dma(uint32_t control, double worst_ns);
    void dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host);
    [[noreturn]] void dma_fault();
    uint64_t read_counter(uint32_t low_offset);
    void upload(const std::vector<FloatBox>& boxes, FramePhases& phases);
    // The chain of six arrays; the delta stream's records of `changed` boxes.
    void upload_full(uint32_t objects);
    void upload_delta(const std::vector<uint32_t>& changed);
    // Boxes whose words differ from the board's copy (all when it is unknown).
    std::vector<uint32_t> changed_boxes(uint32_t objects) const;
    // Host RAM areas (byte offsets), from the capacity, pair buffer and config.
    uint64_t pair_area() const;
    uint64_t delta_area() const;
    uint64_t descriptor_area() const;
    // Waits for the board after START or RESUME; returns its status (an
    // error status fails the frame).
    uint32_t wait_for_board(uint32_t objects);
    void read_pairs(PairList& pairs, uint32_t objects, FramePhases& phases);

    HostPort& port_;
    SimTime period_;
    DriverConfig config_;
    uint32_t capacity_ = 0;
    uint32_t buffer_depth_ = 0;
    uint32_t parallelism_ = 1;
    NumberFormat format_;
    uint64_t cycles_seen_ = 0;
    double spent_[kPhases] = {};
    SimTime mark_ = 0;
    SimTime noticed_ = 0;  // when the last wait_for noticed its event
    std::shared_ptr<const BusTiming> bus_;
    std::optional<FrameTime> time_;  // from open(), once the board's m and pair buffer are known
    uint32_t timeouts_recovered_ = 0;
    // The board's memories as the last upload left them (the words of each
    // coordinate, boxes 0..shadow_objects_-1), for delta uploads; invalid
    // until a frame succeeds, and after any fault.
    std::array<std::vector<uint32_t>, kCoordinates> shadow_;
    uint32_t shadow_objects_ = 0;
    bool shadow_valid_ = false;
};

}  // namespace cdvp
