#include "platform/driver/driver_sequence.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
#include "models/pci/dma_registers.h"
#include "platform/driver/closed_form.h"
#include "platform/driver/driver_text.h"
#include "platform/driver/frame_time.h"
#include "platform/driver/port_executor.h"

namespace cdvp {

using R = ControlRegisters;
using D = DmaRegisters;

template <class X>
DriverSequence<X>::DriverSequence(X& executor, const DriverConfig& config, SimTime period_fs)
    : x_(executor), config_(config), period_(period_fs) {}

template <class X>
void DriverSequence<X>::open(uint32_t box_banks, uint32_t pair_bank) {
    box_banks_ = box_banks;
    pair_bank_ = pair_bank;
    show_pair_bank(R::kCurrentPairs);
    in_flight_.reset();
}

template <class X>
void DriverSequence<X>::charge(Phase phase) {
    account_->spent[phase] += X::span(x_.now() - mark_);
    mark_ = x_.now();
}

template <class X>
void DriverSequence<X>::show_pair_bank(uint32_t bank) {
    if (pair_bank_ == bank) return;
    x_.write(R::kPairBank, bank);
    pair_bank_ = bank;
}

template <class X>
void DriverSequence<X>::cpu_work(double ns) {
    x_.cpu(ns);
    charge(kDriver);
}

template <class X>
uint64_t DriverSequence<X>::read_counter(uint32_t low_offset) {
    const uint64_t low = x_.read(low_offset);
    return low | uint64_t{x_.read(low_offset + 4)} << 32;
}

// By interrupt: each interrupt (the line is shared) or the timeout is
// followed by one status read. By polling: status reads until the deadline.
template <class X>
uint32_t DriverSequence<X>::wait_for(uint64_t status_address, uint32_t bits, SimTime timeout, const char* what,
                                     bool by_interrupt, bool check_first) {
    const SimTime deadline = x_.deadline_after(timeout);
    const auto timed_out = [&] {
        return DeviceFault(std::string(what) + " timed out: no completion within " + microseconds(timeout) +
                           " of simulated time");
    };
    if (!by_interrupt) {
        noticed_ = x_.now();
        const uint32_t value = x_.poll(status_address, bits, deadline);
        noticed_ = x_.now();  // a poll notices when its read returns
        if (!(value & bits)) throw timed_out();
        return value;
    }
    // A sweep in flight shares the line with a DMA: an event of the board's
    // that came while the host was busy keeps the line up, and the DMA's
    // completion would raise no edge. The handler acknowledges it first.
    const bool shared_with_sweep = in_flight_ && status_address != R::kStatus;
    if (shared_with_sweep) acknowledge_board_event();
    bool look_now = check_first;
    SimTime looked = x_.now();
    for (uint32_t waits = 0;; ++waits) {
        // After a status read that did not show the event, an interrupt
        // that came during it was for what it could not see yet: look again
        // instead of waiting for another.
        if (!look_now) {
            if (waits > 0 || check_first) x_.wait_for_interrupt_since(looked, deadline - x_.now(), status_address);
            else x_.wait_for_interrupt(deadline - x_.now(), status_address);
        }
        look_now = false;
        noticed_ = x_.now();  // the handler runs: the status read is readback work
        looked = x_.now();
        const uint32_t value = x_.read(status_address);
        const bool late = x_.now() >= deadline;
        if (value & bits) {
            if (late) ++account_->timeouts_recovered;  // the interrupt was lost
            return value;
        }
        if (late) throw timed_out();
        // Woken by the board's event, not the DMA's: acknowledge it and look
        // at the DMA again.
        if (shared_with_sweep) look_now = acknowledge_board_event();
    }
}

template <class X>
bool DriverSequence<X>::acknowledge_board_event() {
    if (!(x_.read(R::kStatus) & R::kInterrupt)) return false;
    x_.write(R::kControl, R::kAcknowledge);
    return true;
}

template <class X>
bool DriverSequence<X>::dma_by_interrupt() const {
    return config_.wait == WaitMode::kIrq && config_.interrupts == InterruptPolicy::kEvery;
}

template <class X>
template <class Worst>
void DriverSequence<X>::run_dma(uint32_t control, Worst worst) {
    const SimTime timeout = x_.timeout(worst);
    x_.write(D::kBase + D::kControl, control | D::kStart | (dma_by_interrupt() ? uint32_t{D::kInterruptOnDone} : 0u));
    const uint32_t status = wait_for(D::kBase + D::kStatus, D::kDone | D::kError, timeout, "DMA", dma_by_interrupt());
    if (status & D::kError) dma_fault();
    x_.write(D::kBase + D::kStatus, D::kDone);  // clear done: the shared line falls
}

template <class X>
template <class Worst>
void DriverSequence<X>::run_chain(Chain chain, uint64_t count, Worst worst) {
    const uint64_t at = x_.stage_chain(chain, count);
    x_.write(D::kBase + D::kChainLo, static_cast<uint32_t>(at));
    x_.write(D::kBase + D::kChainHi, static_cast<uint32_t>(at >> 32));
    run_dma(D::kChain, worst);
}

template <class X>
void DriverSequence<X>::dma_fault() {
    const auto cause = static_cast<DmaFault>(x_.read(D::kBase + D::kErrorCause));
    const uint64_t address = read_counter(D::kBase + D::kErrorAddressLo);
    if (cause == DmaFault::kMasterAbort && address >= x_.memory_size()) {
        throw DeviceFault("DMA fault: host address " + hex(address) + " beyond host memory (" +
                          mebibytes(x_.memory_size()) + ")");
    }
    throw DeviceFault(std::string("DMA fault: ") + describe(cause) + " at address " + hex(address));
}

template <class X>
void DriverSequence<X>::dma(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host) {
    x_.write(D::kBase + D::kHostAddressLo, static_cast<uint32_t>(host_address));
    x_.write(D::kBase + D::kHostAddressHi, static_cast<uint32_t>(host_address >> 32));
    x_.write(D::kBase + D::kLocalAddress, local_address);
    x_.write(D::kBase + D::kBytes, bytes);
    const Direction direction = to_host ? Direction::kToHost : Direction::kToBoard;
    run_dma(to_host ? uint32_t{D::kToHost} : 0u,
            [&](const FrameTime& time) { return time.dma_worst_ns(bytes, direction); });
}

template <class X>
void DriverSequence<X>::upload(const Frame& frame) {
    FramePhases& phases = account_->phases;
    const uint32_t n = x_.objects(frame);
    // In the board's format: float32 bit patterns, or fixed-point codes over
    // the frame's bounds, rounded outward.
    x_.stage(frame);
    if (n == 0) return;
    // Packing and comparing with the board's copy, done natively.
    cpu_work(config_.call_ns + config_.ns_per_box * n);
    const bool may_delta = config_.upload != UploadMode::kFull;
    const uint64_t changed = may_delta ? x_.changed_boxes(frame) : n;
    if (may_delta && upload_as_delta(config_, x_.bus(), n, changed)) {
        upload_delta(changed);
        phases.boxes_sent = static_cast<uint32_t>(changed);
        phases.upload_bytes = address_map::kDeltaRecordBytes * changed;
    } else {
        upload_full(n);
        phases.boxes_sent = n;
        phases.upload_bytes = uint64_t{24} * n;
    }
    charge(kUpload);
    // The host's bank holds these words now (the frame's faults invalidate them).
    if (may_delta) x_.keep_bank();
}

template <class X>
void DriverSequence<X>::upload_full(uint32_t n) {
    if (config_.transfer != Transfer::kDma) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            x_.pio_write(address_map::coordinate_window(c), x_.host_address(HostArea::kCoordinates, c), 4 * n);
        }
        return;
    }
    // One scatter-gather chain of six descriptors: one set-up, one interrupt.
    run_chain(Chain::kCoordinateArrays, n, [n](const FrameTime& time) { return time.upload_worst_ns(n); });
}

// The records (index, six words) in host RAM, then one chain of
// window-sized pieces into the stream, or programmed writes of them.
template <class X>
void DriverSequence<X>::upload_delta(uint64_t changed) {
    if (changed == 0) return;
    x_.stage_delta_records();
    const uint64_t bytes = address_map::kDeltaRecordBytes * changed;
    const auto stream = static_cast<uint32_t>(address_map::kDeltaStream);
    if (config_.transfer != Transfer::kDma) {
        const uint64_t records = x_.host_address(HostArea::kDeltaRecords);
        for (uint64_t done = 0; done < bytes;) {
            const auto piece = static_cast<uint32_t>(std::min<uint64_t>(bytes - done, address_map::kDeltaStreamSize));
            x_.pio_write(stream, records + done, piece);
            done += piece;
        }
        return;
    }
    run_chain(Chain::kDeltaStream, changed, [changed](const FrameTime& time) { return time.delta_worst_ns(changed); });
}

template <class X>
uint32_t DriverSequence<X>::wait_for_board(uint32_t objects, bool check_first) {
    const SimTime waiting_from = mark_;
    const SimTime timeout = x_.timeout([objects](const FrameTime& time) { return time.board_worst_ns(objects); });
    const bool by_interrupt = config_.wait == WaitMode::kIrq;
    const uint32_t status =
        wait_for(R::kStatus, R::kDone | R::kOverflow | R::kError, timeout, "board", by_interrupt, check_first);
    mark_ = noticed_;
    if (by_interrupt) x_.write(R::kControl, R::kAcknowledge);
    if (status & R::kError) {
        throw DeviceFault(std::string("board error status: ") + R::describe(x_.read(R::kErrorCause)));
    }
    // The segment ran cycles x period from its command. The host waited
    // from waiting_from to noticing it: the part of the sweep within that
    // is compute, the rest the notification's lag; the sweep before it ran
    // beside the host's work on other frames (pipelined), hidden.
    const uint64_t cycles = read_counter(R::kCyclesLo);
    Account& account = *account_;
    const Time busy = X::span(period_ * (cycles - account.cycles_seen));
    account.cycles_seen = cycles;
    const Time waited = X::span(mark_ - waiting_from);
    const Time ran_before =
        waiting_from > account.segment_start ? X::span(waiting_from - account.segment_start) : Time{};
    const Time exposed = std::min(busy > ran_before ? busy - ran_before : Time{}, waited);
    account.spent[kCompute] += exposed;
    account.spent[kIrq] += waited - exposed;
    account.phases.overlap_ns += X::ns(busy - exposed);
    return status;
}

// PAIR_COUNT bounds the pairs before any is copied; in an encoded format
// PAIR_WORDS gives the words to move, and the decoded pairs must be as many.
template <class X>
void DriverSequence<X>::read_pairs(Pairs& pairs, uint32_t objects) {
    Account& account = *account_;
    const uint32_t count = x_.read(R::kPairCount);
    if (count == 0) return;
    config_.pair_budget.check(account.pairs_read + count);
    const bool list = config_.pair_format == PairFormat::kList;
    const uint64_t words = list ? 2 * uint64_t{count} : x_.read(R::kPairWords);
    if (!x_.pair_area_holds(words)) {
        throw DeviceFault("the board's pair window holds " + std::to_string(words) + " words, more than " +
                          std::to_string(count) + " pairs can encode to");
    }
    const uint64_t area = x_.host_address(HostArea::kPairs);
    const auto bytes = static_cast<uint32_t>(4 * words);
    if (config_.transfer == Transfer::kDma) {
        dma(area, static_cast<uint32_t>(address_map::kPairBuffer), bytes, true);
    } else {
        x_.pio_read(address_map::kPairBuffer, area, bytes);
    }
    charge(kReadback);
    account.phases.readback_bytes += bytes;
    x_.take_pairs(pairs, words, count, objects);
    account.pairs_read += count;
    cpu_work(config_.ns_per_pair * count);
}

template <class X>
void DriverSequence<X>::abandon() {
    in_flight_.reset();
    in_flight_pairs_.clear();
}

template <class X>
void DriverSequence<X>::open_account(Account& account, uint32_t objects) {
    account = Account{};
    account.objects = objects;
    account.began = x_.now();
    account_ = &account;
    mark_ = account.began;
}

template <class X>
FramePhases DriverSequence<X>::close_account(Account& account, bool pipelined_frame) {
    FramePhases phases = account.phases;
    phases.upload_ns = X::ns(account.spent[kUpload]);
    phases.start_ns = X::ns(account.spent[kStart]);
    phases.compute_ns = X::ns(account.spent[kCompute]);
    phases.irq_ns = X::ns(account.spent[kIrq]);
    phases.readback_ns = X::ns(account.spent[kReadback]);
    phases.driver_ns = X::ns(account.spent[kDriver]);
    phases.latency_ns = ns_from_fs(x_.now() - account.began);
    // One frame at a time, the host worked on it throughout; pipelined, the
    // host's time on it is what was charged to it.
    Time charged{};
    for (Time spent : account.spent) charged += spent;
    phases.total_ns = pipelined_frame ? X::ns(charged) : phases.latency_ns;
    phases.timeouts_recovered = account.timeouts_recovered;
    return phases;
}

template <class X>
void DriverSequence<X>::start_sweep(Account& account) {
    x_.write(R::kObjectCount, account.objects);
    x_.write(R::kControl, R::kStart);
    charge(kStart);
    account.segment_start = mark_;
    account.cycles_seen = 0;
    if (box_banks_ > 1) x_.banks_swapped();  // START hands the bank over
}

template <class X>
uint64_t DriverSequence<X>::finish_sweep(Account& account, Pairs& pairs, bool check_first, bool defer_last) {
    for (bool first = true;; first = false) {
        const uint32_t status = wait_for_board(account.objects, check_first && first);
        if (status & R::kOverflow) {
            show_pair_bank(R::kCurrentPairs);
            read_pairs(pairs, account.objects);
            ++account.phases.overflow_pauses;
            x_.write(R::kControl, R::kResume);
            charge(kReadback);
            account.segment_start = mark_;
            continue;
        }
        if (!(status & R::kDone)) throw DeviceFault("board interrupt with unexpected status " + hex(status));
        if (!defer_last) {
            show_pair_bank(R::kCurrentPairs);
            read_pairs(pairs, account.objects);
        }
        break;
    }
    account.phases.compute_cycles = account.cycles_seen;
    account.phases.stall_cycles = read_counter(R::kStallsLo);
    return read_counter(R::kTotalPairsLo);
}

template <class X>
void DriverSequence<X>::check_found(uint64_t found, const Account& account) {
    if (found != account.pairs_read) {
        throw DeviceFault("the board found " + std::to_string(found) + " pairs but " +
                          std::to_string(account.pairs_read) + " were read back");
    }
}

template <class X>
FramePhases DriverSequence<X>::frame(const Frame& frame, Pairs& pairs) {
    pairs.clear();
    Account account;
    open_account(account, x_.objects(frame));
    upload(frame);
    start_sweep(account);
    const uint64_t found = finish_sweep(account, pairs, false, false);
    charge(kReadback);
    check_found(found, account);
    return close_account(account, false);
}

// Frames pipelined on a board with two box banks: the host uploads frame k+1
// into one bank while the board sweeps frame k in the other, and reads frame
// k's pairs back from the previous pair buffer while frame k+1 sweeps
// (docs/communication.md). Each frame keeps its own account of the host's
// time, so a frame's phases add up to the host's time on it and the frames'
// totals to the run's simulated time; its latency spans two calls.
template <class X>
bool DriverSequence<X>::submit(const Frame& frame, Pairs& pairs, FramePhases& phases) {
    Account next;
    open_account(next, x_.objects(frame));
    // Into the host's bank while the board sweeps the frame in flight.
    upload(frame);
    const bool finishing = in_flight_.has_value();
    uint64_t found = 0;
    if (finishing) {
        account_ = &*in_flight_;
        found = finish_sweep(*in_flight_, in_flight_pairs_, true, true);
        charge(kReadback);
    }
    account_ = &next;
    start_sweep(next);
    if (finishing) {
        // The finished frame's last pairs, from the previous pair buffer,
        // while the new frame sweeps.
        account_ = &*in_flight_;
        show_pair_bank(R::kPreviousPairs);
        read_pairs(in_flight_pairs_, in_flight_->objects);
        charge(kReadback);
        check_found(found, *in_flight_);
        phases = close_account(*in_flight_, true);
        pairs.swap(in_flight_pairs_);
    }
    in_flight_ = next;
    account_ = &*in_flight_;
    in_flight_pairs_.clear();
    return finishing;
}

template <class X>
bool DriverSequence<X>::finish(Pairs& pairs, FramePhases& phases) {
    if (!in_flight_) return false;
    account_ = &*in_flight_;
    mark_ = x_.now();
    const uint64_t found = finish_sweep(*in_flight_, in_flight_pairs_, true, false);
    charge(kReadback);
    check_found(found, *in_flight_);
    phases = close_account(*in_flight_, true);
    pairs.swap(in_flight_pairs_);
    in_flight_.reset();
    in_flight_pairs_.clear();
    return true;
}

template class DriverSequence<PortExecutor>;
template class DriverSequence<ClosedForm>;

}  // namespace cdvp
