// The host driver of the collision board: host software that reaches the
// board over the PCI bus and stages data in host RAM, all through a HostPort.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/board/tile_config.h"
#include "models/common/aabb.h"
#include "models/common/pair_budget.h"
#include "models/number_format/number_format.h"
#include "models/pci/bus_timing.h"
#include "sw/driver/host_port.h"

namespace cdvp {

// The simulated system faulted (a DMA or bus fault, a board error status, a
// driver timeout): the input was fine. The frame produced no pairs.
class DeviceFault : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A frame would run the simulated clock past what SystemC can represent
// (2^64 fs, about 5.1 hours): refused before the board starts.
class SimulatedTimeLimit : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct DriverConfig {
    bool use_dma = true;          // false: boxes and pairs by programmed I/O
    bool use_interrupts = true;   // false: poll the status register
    double poll_gap_ns = 0.0;     // CPU time between two status polls
    // Host CPU work, per frame (assumptions of the host preset): packing a box
    // (six double-to-float conversions and stores), unpacking a pair, and a
    // call into the kernel driver per board operation.
    double ns_per_box = 0.0;
    double ns_per_pair = 0.0;
    double call_ns = 0.0;
    // Simulated-time timeouts: a wait for the DMA engine or the board gives
    // up after timeout_factor x its worst-case time plus timeout_floor_ns
    // (worst case: the bus's DMA time, or every sweep cycle plus a full pair
    // buffer's drain, plus an interrupt). On timeout the driver polls the
    // status once (a lost interrupt recovers) and otherwise fails the frame.
    double timeout_factor = 2.0;
    double timeout_floor_ns = 100000.0;
    // The board's memory as its bitstream was built (block RAM or SSRAM
    // tiles): the driver knows it as it knows the board it loaded; it bounds
    // the sweep's cycles. Not a setting: the platform copies the board's.
    TileConfig tiles;
    // The most pairs a frame may hold (run.max_pairs): the read-back stops
    // with PairBudgetExceeded before the pairs past it are copied. Not a
    // setting of its own: the platform passes the run's budget.
    PairBudget pair_budget{};
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
    uint32_t overflow_pauses = 0;
    uint32_t timeouts_recovered = 0;  // waits whose interrupt never came, finished by polling STATUS
};

class BoardDriver {
public:
    // port: the host the driver runs on; period_fs: the board's clock period;
    // bus: the timing the timeouts are derived from.
    BoardDriver(HostPort& port, SimTime period_fs, const DriverConfig& config, std::shared_ptr<const BusTiming> bus);

    // Host RAM the driver needs for a board of this capacity and pair buffer.
    static uint64_t host_memory_bytes(uint32_t capacity, uint32_t buffer_depth);

    // Checks the board's identity and reads its capacity and number format.
    void open();
    uint32_t capacity() const { return capacity_; }
    // The board's comparators' format (its FORMAT register): the driver
    // writes boxes in it (sw/driver/quantiser.h).
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
    void poll_pause();

    uint32_t read(uint64_t address);
    void write(uint64_t address, uint32_t value);
    void pio_read(uint64_t address, void* data, uint32_t length);
    void pio_write(uint64_t address, const void* data, uint32_t length);
    FramePhases frame(const std::vector<FloatBox>& boxes, PairList& pairs);
    // Stops the DMA engine and the board and clears their status (best effort).
    void recover();
    // How long a wait whose worst case is expected_ns may take; refuses a
    // deadline past the simulator's clock.
    SimTime timeout_for(double expected_ns) const;
    // Waits for the interrupt or a poll to find any of bits in the register's
    // value, until the timeout; returns the value. what names the wait.
    uint32_t wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what);
    void run_dma(uint32_t control, double expected_ns);
    void dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host);
    [[noreturn]] void dma_fault();
    uint64_t read_counter(uint32_t low_offset);
    void upload(const std::vector<FloatBox>& boxes);
    // Waits for the board after START or RESUME; returns its status (an
    // error status fails the frame).
    uint32_t wait_for_board(uint32_t objects);
    void read_pairs(PairList& pairs);

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
    uint32_t timeouts_recovered_ = 0;
};

}  // namespace cdvp
