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
    // On a board with two box banks (frames pipelined): the frame's sweep
    // time hidden behind the host's work on the frames beside it (not in
    // total_ns, which is the host's time on this frame), and the frame's
    // latency, from the start of its upload to its last pair in host memory.
    // One frame at a time: overlap 0 and latency = total.
    double overlap_ns = 0;
    double latency_ns = 0;
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

    // Frames pipelined, on a board with two box banks (BOX_BANKS = 2): two
    // frames in flight. submit() uploads `boxes` into the host's bank while
    // the board sweeps the frame before, waits for that frame's end, starts
    // the new frame and reads the finished frame's pairs back during the new
    // sweep: it returns true with them (pairs, *phases) when a frame
    // finished, false on the first call. finish() completes the frame in
    // flight the same way (false when none is). Faults are run_frame's; after
    // one no frame is in flight.
    bool pipelined() const { return box_banks_ > 1; }
    bool submit(const std::vector<FloatBox>& boxes, PairList& pairs, FramePhases& phases);
    bool finish(PairList& pairs, FramePhases& phases);

private:
    enum Phase { kUpload, kStart, kCompute, kIrq, kReadback, kDriver, kPhases };
    // One frame's book while the driver works on it: the host time charged
    // to it by phase, what it moved, and where its sweep stands.
    struct FrameAccount {
        double spent[kPhases] = {};
        FramePhases phases;
        SimTime began = 0;          // its upload began: its latency counts from here
        SimTime segment_start = 0;  // its last START or RESUME
        uint64_t cycles_seen = 0;
        uint32_t objects = 0;
        uint32_t timeouts_recovered = 0;
    };
    void charge(Phase phase);  // the time since the last charge goes to phase of the current account
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
    // check_first: read the status before any wait (the event may have come
    // while the host was busy: frames pipelined).
    uint32_t wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what, bool by_interrupt,
                      bool check_first = false);
    // The shared line's handler while a sweep runs beside a DMA: an
    // interrupt that was not the DMA's is the board's; it is acknowledged so
    // that the line can rise for the DMA. Returns whether it was the board's.
    bool acknowledge_board_event();
    bool dma_by_interrupt() const;
    void run_dma(uint32_t control, double worst_ns);
    void dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host);
    [[noreturn]] void dma_fault();
    uint64_t read_counter(uint32_t low_offset);
    void upload(const std::vector<FloatBox>& boxes);
    // The chain of six arrays; the delta stream's records of `changed` boxes.
    void upload_full(uint32_t objects);
    void upload_delta(const std::vector<uint32_t>& changed);
    // Boxes whose words differ from the host bank's copy (all when it is unknown).
    std::vector<uint32_t> changed_boxes(uint32_t objects) const;
    // Starts an account; the frame's phases from it, ending now.
    void open_account(FrameAccount& account, uint32_t objects);
    // pipelined_frame: its total is the host time charged to it, not the
    // time from its start (frames overlapped).
    FramePhases close_account(FrameAccount& account, bool pipelined_frame);
    // Fails the frame unless the pairs read back are as many as the board found.
    static void check_found(uint64_t found, const PairList& pairs);
    // START of the account's frame (its boxes uploaded), the banks swapping.
    void start_sweep(FrameAccount& account);
    // Waits for the account's sweep to end, reading its pairs at each
    // overflow pause and resuming; returns with it done, counters read.
    // defer_last: leave the last segment's pairs in the buffer (pipelined:
    // they are read from the previous pair buffer during the next sweep).
    // Returns the pairs the board found (TOTAL_PAIRS).
    uint64_t finish_sweep(FrameAccount& account, PairList& pairs, bool check_first, bool defer_last);
    // Shows the current or the previous pair buffer (PAIR_BANK), written only on a change.
    void show_pair_bank(uint32_t bank);
    // Refuses a frame of more boxes than the board holds (invalid_argument).
    void check_capacity(const std::vector<FloatBox>& boxes) const;
    // Fails with what recover() leaves: no pairs, no frame in flight.
    void fail_frames(PairList& pairs);
    // Host RAM areas (byte offsets), from the capacity, pair buffer and config.
    uint64_t pair_area() const;
    uint64_t delta_area() const;
    uint64_t descriptor_area() const;
    // Waits for the board after START or RESUME; returns its status (an
    // error status fails the frame).
    uint32_t wait_for_board(uint32_t objects, bool check_first = false);
    void read_pairs(PairList& pairs, uint32_t objects);

    HostPort& port_;
    SimTime period_;
    DriverConfig config_;
    uint32_t capacity_ = 0;
    uint32_t buffer_depth_ = 0;
    uint32_t parallelism_ = 1;
    NumberFormat format_;
    uint32_t box_banks_ = 1;
    uint32_t host_bank_ = 0;   // the bank the next upload goes to
    uint32_t pair_bank_ = 0;   // what PAIR_BANK shows
    FrameAccount* account_ = nullptr;  // the frame the host works on now
    // Pipelined: the frame the board sweeps (uploaded and started), and its pairs so far.
    std::optional<FrameAccount> in_flight_;
    PairList in_flight_pairs_;
    SimTime mark_ = 0;
    SimTime noticed_ = 0;  // when the last wait_for noticed its event
    std::shared_ptr<const BusTiming> bus_;
    std::optional<FrameTime> time_;  // from open(), once the board's m and pair buffer are known
    // Each bank's memories as the last upload into it left them (the words
    // of each coordinate, boxes 0..objects-1), for delta uploads; invalid
    // until a frame succeeds, and after any fault.
    struct BankShadow {
        std::array<std::vector<uint32_t>, kCoordinates> words;
        uint32_t objects = 0;
        bool valid = false;
    };
    std::array<BankShadow, 2> shadow_;
    void forget_shadows() {
        for (BankShadow& bank : shadow_) bank.valid = false;
    }
};

}  // namespace cdvp
