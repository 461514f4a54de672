// The driver's frame written once: every bus and board operation the driver
// issues for a frame, in its order, and where each one's time goes. One
// frame at a time (upload, START, the waits, the read-back at each overflow
// pause and RESUME, the counters), or frames pipelined on two box banks
// (submit: the next frame's upload beside the sweep in flight, its end, the
// next START, the finished frame's last pairs from the previous pair buffer
// during the new sweep; finish). DMA or PIO, full or delta uploads, every
// pair format, waits by interrupt (the line shared with the DMA engine while
// a sweep runs) or by polling with back-off, and the timeouts.
//
// Two executors run it, so that both levels follow every change made here:
// - PortExecutor (port_executor.h) performs each operation through a HostPort:
//   BoardDriver on the SystemC platform or on any host;
// - ClosedForm (closed_form.h) evaluates each operation's time from the
//   BusTiming formulas and the sweep's plan, the board answering from the
//   plan: the analytic level (AnalyticFrame, AnalyticPipeline).
//
// An executor X gives:
// - X::Frame, X::Pairs: what a frame is (its boxes; its plan) and where its
//   pairs go; X::Time, X::span(SimTime), X::ns(Time): what a phase is summed
//   in (the platform's driver in ns as it always has, the closed forms in
//   exact femtoseconds);
// - the bus, the board and the host's clock: now(), read(), write(),
//   pio_write(), pio_read(), cpu(ns), timeout(worst), deadline_after(),
//   wait_for_interrupt(), wait_for_interrupt_since(), poll() (a closed form
//   does not walk the polls one by one), memory_size();
// - the host's data: objects(), stage() (the boxes in the board's format),
//   changed_boxes(), keep_bank(), stage_delta_records(), stage_chain(),
//   host_address(), pair_area_holds(), take_pairs(), banks_swapped(), bus().
#pragma once

#include <cstdint>
#include <optional>

#include "models/common/aabb.h"
#include "platform/driver/driver_config.h"
#include "platform/driver/frame_phases.h"
#include "platform/driver/host_port.h"

namespace cdvp {

// Where host memory holds what the board's DMA engine moves.
enum class HostArea : uint8_t { kCoordinates, kPairs, kDeltaRecords };
// A scatter-gather chain in host memory: the six coordinate arrays, or the
// delta stream's records in window-sized pieces.
enum class Chain : uint8_t { kCoordinateArrays, kDeltaStream };

template <class X>
class DriverSequence {
public:
    using Frame = typename X::Frame;
    using Pairs = typename X::Pairs;
    using Time = typename X::Time;

    // executor outlives this; period_fs: the board's clock period.
    DriverSequence(X& executor, const DriverConfig& config, SimTime period_fs);

    // With the board open: its box banks (2: frames pipelined) and the pair
    // bank it shows; shows the current pairs. No frame in flight.
    void open(uint32_t box_banks, uint32_t pair_bank);
    bool pipelined() const { return box_banks_ > 1; }
    bool in_flight() const { return in_flight_.has_value(); }

    // BoardDriver::run_frame, submit and finish (board_driver.h), faults
    // thrown as they come: the caller recovers, then abandon()s.
    FramePhases frame(const Frame& frame, Pairs& pairs);
    bool submit(const Frame& frame, Pairs& pairs, FramePhases& phases);
    bool finish(Pairs& pairs, FramePhases& phases);
    // After a fault: no frame in flight, its pairs dropped.
    void abandon();

private:
    enum Phase { kUpload, kStart, kCompute, kIrq, kReadback, kDriver, kPhases };
    // One frame's book while the driver works on it: the host time charged
    // to it by phase, what it moved, and where its sweep stands.
    struct Account {
        Time spent[kPhases] = {};
        FramePhases phases;
        SimTime began = 0;          // its upload began: its latency counts from here
        SimTime segment_start = 0;  // its last START or RESUME
        uint64_t cycles_seen = 0;
        uint64_t pairs_read = 0;
        uint32_t objects = 0;
        uint32_t timeouts_recovered = 0;
    };

    void charge(Phase phase);  // the time since the last charge goes to phase of the current account
    void cpu_work(double ns);  // host CPU time, charged to the driver
    uint64_t read_counter(uint32_t low_offset);
    // Waits for the interrupt or a poll to find any of bits in the register's
    // value, until the timeout; returns the value. what names the wait.
    // by_interrupt: wait for the interrupt (else poll). check_first: read
    // the status before any wait (the event may have come while the host
    // was busy: frames pipelined).
    uint32_t wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what, bool by_interrupt,
                      bool check_first = false);
    // The shared line's handler while a sweep runs beside a DMA: an
    // interrupt that was not the DMA's is the board's; it is acknowledged so
    // that the line can rise for the DMA. Returns whether it was the board's.
    bool acknowledge_board_event();
    bool dma_by_interrupt() const;
    // Starts the bridge's DMA engine (registers already set) and waits for
    // it; worst(FrameTime) gives the wait's worst case; a fault fails the frame.
    template <class Worst>
    void run_dma(uint32_t control, Worst worst);
    // The chain staged in host memory (its descriptors' address in two
    // registers), then the DMA that walks it.
    template <class Worst>
    void run_chain(Chain chain, uint64_t count, Worst worst);
    [[noreturn]] void dma_fault();
    void dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host);
    void upload(const Frame& frame);
    void upload_full(uint32_t objects);
    void upload_delta(uint64_t changed);
    // Starts an account; the frame's phases from it, ending now.
    void open_account(Account& account, uint32_t objects);
    // pipelined_frame: its total is the host time charged to it, not the
    // time from its start (frames overlapped).
    FramePhases close_account(Account& account, bool pipelined_frame);
    // Fails the frame unless the pairs read back are as many as the board found.
    static void check_found(uint64_t found, const Account& account);
    // START of the account's frame (its boxes uploaded), the banks swapping.
    void start_sweep(Account& account);
    // Waits for the account's sweep to end, reading its pairs at each
    // overflow pause and resuming; returns with it done, counters read.
    // defer_last: leave the last segment's pairs in the buffer (pipelined:
    // they are read from the previous pair buffer during the next sweep).
    // Returns the pairs the board found (TOTAL_PAIRS).
    uint64_t finish_sweep(Account& account, Pairs& pairs, bool check_first, bool defer_last);
    // Shows the current or the previous pair buffer (PAIR_BANK), written only on a change.
    void show_pair_bank(uint32_t bank);
    // Waits for the board after START or RESUME; returns its status (an
    // error status fails the frame).
    uint32_t wait_for_board(uint32_t objects, bool check_first = false);
    void read_pairs(Pairs& pairs, uint32_t objects);

    X& x_;
    DriverConfig config_;
    SimTime period_;
    uint32_t box_banks_ = 1;
    uint32_t pair_bank_ = 0;     // what PAIR_BANK shows
    Account* account_ = nullptr;  // the frame the host works on now
    // Pipelined: the frame the board sweeps (uploaded and started), and its pairs so far.
    std::optional<Account> in_flight_;
    Pairs in_flight_pairs_;
    SimTime mark_ = 0;
    SimTime noticed_ = 0;  // when the last wait_for noticed its event
};

}  // namespace cdvp
