#include "platform/driver/closed_form.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/common/integer_math.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
#include "models/pair_collector/pair_format.h"
#include "models/pci/dma_registers.h"
#include "platform/driver/driver_text.h"
#include "platform/driver/frame_time.h"

namespace cdvp {

using R = ControlRegisters;
using D = DmaRegisters;

namespace {
[[noreturn]] void unmodelled(const char* access, uint64_t address) {
    throw std::logic_error(std::string("the closed form models no ") + access + " at " + hex(address) +
                           ": the driver's sequence uses a register platform/driver/closed_form.cpp does not answer");
}
}  // namespace

ClosedForm::ClosedForm(const DriverConfig& driver, const BusTiming& bus, const AnalyticBoard& board)
    : driver_(driver), bus_(bus), board_(board) {
    board_.buffer_depth = std::max<uint32_t>(board_.buffer_depth, 1);
    board_.drain_per_cycle = std::max<uint32_t>(board_.drain_per_cycle, 1);
    read_ = read_fs();
    write_ = write_fs();
    lag_ = fs_from_ns(bus_.interrupt_ns());
}

// The bus annotates words x the per-word time as one delay (PciBus).
SimTime ClosedForm::read_fs(uint64_t words) const {
    return fs_from_ns(static_cast<double>(words) * bus_.pio_read_ns());
}

SimTime ClosedForm::write_fs(uint64_t words) const {
    return fs_from_ns(static_cast<double>(words) * bus_.pio_write_ns());
}

// Polls read at R, R + (g0 + R), R + (g0 + R) + (g1 + R), ... after the
// command; a read sees the state at its end. Between two polls the driver
// waits the poll gap (a board period on an untimed gap), growing under
// back-off until it stops growing, from where the polls are evenly spaced.
SimTime ClosedForm::poll_notice_fs(SimTime event_fs) const {
    const SimTime read = read_fs();
    SimTime t = read;
    for (uint32_t k = 0; t < event_fs; ++k) {
        const SimTime gap = poll_gap_fs(driver_, board_.period_fs, k);
        if (k >= 64 || gap == poll_gap_fs(driver_, board_.period_fs, k + 1)) {
            const SimTime period = gap + read;
            return t + ceil_div(event_fs - t, period) * period;
        }
        t += gap + read;
    }
    return t;
}

// DMA: one chain of six descriptors, each fetched (a 24-byte read) before
// its array moves, summed in the bridge's order.
double ClosedForm::upload_bus_ns(uint32_t objects) const {
    double chain_ns = 0;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        chain_ns += bus_.dma_ns(sizeof(DmaDescriptor), Direction::kToBoard);
        chain_ns += bus_.dma_ns(4 * uint64_t{objects}, Direction::kToBoard);
    }
    return chain_ns;
}

uint64_t ClosedForm::stage_chain(Chain chain, uint64_t count) {
    chain_ns_ = chain == Chain::kCoordinateArrays ? upload_bus_ns(static_cast<uint32_t>(count))
                                                  : delta_upload_bus_ns(bus_, Transfer::kDma, count);
    return 0;
}

const FramePlan* ClosedForm::shown(uint64_t& segment) const {
    if (pair_bank_ == R::kPreviousPairs) {
        segment = previous_ == nullptr ? 0 : previous_->sweep.segments() - 1;
        return previous_;
    }
    segment = segment_;
    return sweeping_;
}

uint32_t ClosedForm::value(uint64_t address) const {
    const auto low = [](uint64_t counter) { return static_cast<uint32_t>(counter); };
    const auto high = [](uint64_t counter) { return static_cast<uint32_t>(counter >> 32); };
    const SweepPlan* sweep = sweeping_ == nullptr ? nullptr : &sweeping_->sweep;
    switch (address) {
        case R::kStatus: {
            uint32_t status = line_.board_high ? uint32_t{R::kInterrupt} : 0u;
            // A segment that ended paused (overflow) unless it was the sweep's last.
            if (sweep != nullptr && segment_end_ <= now_) {
                status |= segment_ + 1 < sweep->segments() ? R::kOverflow : R::kDone;
            }
            return status;
        }
        case R::kCyclesLo: return low(cycles_);
        case R::kCyclesLo + 4: return high(cycles_);
        case R::kStallsLo: return sweep == nullptr ? 0 : low(sweep->stalls);
        case R::kStallsLo + 4: return sweep == nullptr ? 0 : high(sweep->stalls);
        case R::kTotalPairsLo: return sweep == nullptr ? 0 : low(sweep->pairs);
        case R::kTotalPairsLo + 4: return sweep == nullptr ? 0 : high(sweep->pairs);
        case R::kPairCount:
        case R::kPairWords: {
            uint64_t k = 0;
            const FramePlan* frame = shown(k);
            if (frame == nullptr) return 0;
            const uint64_t count = frame->sweep.segment_pairs(k);
            if (address == R::kPairCount) return static_cast<uint32_t>(count);
            if (frame->pairs == nullptr || count == 0) return static_cast<uint32_t>(2 * count);
            const IndexPair* first = frame->pairs + k * frame->sweep.depth;
            return static_cast<uint32_t>(encoded_words(driver_.pair_format, first, count, frame->objects));
        }
        case D::kBase + D::kStatus: return dma_end_ <= now_ ? uint32_t{D::kDone} : uint32_t{D::kBusy};
        default: unmodelled("register read", address);
    }
}

SimTime ClosedForm::event_at(uint64_t address) const {
    if (address == R::kStatus) return segment_end_;
    if (address == D::kBase + D::kStatus) return dma_end_;
    unmodelled("wait", address);
}

uint32_t ClosedForm::read(uint64_t address) {
    now_ += read_;
    advance(now_);  // a read sees the state at its end
    return value(address);
}

void ClosedForm::start_segment(SimTime at) {
    const uint64_t cycles = sweeping_->sweep.segment_cycles(segment_);
    cycles_ += cycles;
    segment_end_ = at + cycles * board_.period_fs;
    line_.board_at = segment_end_;
}

// A write takes effect at its end.
void ClosedForm::write(uint64_t address, uint32_t value) {
    now_ += write_;
    advance(now_);
    switch (address) {
        case R::kObjectCount: return;  // the plan's
        case R::kPairBank: pair_bank_ = value; return;
        case R::kControl:
            if (value & R::kAcknowledge) line_.board_high = false;
            if (value & R::kStart) {
                previous_ = sweeping_;
                sweeping_ = staged_;
                segment_ = 0;
                cycles_ = 0;
                start_segment(now_);
            } else if (value & R::kResume) {
                ++segment_;
                start_segment(now_);
            }
            return;
        case D::kBase + D::kHostAddressLo:
        case D::kBase + D::kHostAddressHi:
        case D::kBase + D::kLocalAddress:
        case D::kBase + D::kChainLo:
        case D::kBase + D::kChainHi: return;
        case D::kBase + D::kBytes: bytes_ = value; return;
        case D::kBase + D::kControl: {
            if (!(value & D::kStart)) return;
            const Direction direction = (value & D::kToHost) ? Direction::kToHost : Direction::kToBoard;
            const double transfer_ns = (value & D::kChain) ? chain_ns_ : bus_.dma_ns(bytes_, direction);
            dma_end_ = now_ + fs_from_ns(transfer_ns);
            if (value & D::kInterruptOnDone) line_.dma_at = dma_end_;
            return;
        }
        case D::kBase + D::kStatus:  // done cleared: the DMA's request falls
            line_.dma_high = false;
            dma_end_ = kNever;
            return;
        default: unmodelled("register write", address);
    }
}

void ClosedForm::woken(SimTime t, uint64_t awaited) {
    now_ = t == kNever ? std::max(now_, event_at(awaited)) : t;
}

void ClosedForm::wait_for_interrupt(SimTime, uint64_t awaited) { woken(next_notification(now_), awaited); }

void ClosedForm::wait_for_interrupt_since(SimTime since, SimTime, uint64_t awaited) {
    woken(notification_since(since, now_), awaited);
}

uint32_t ClosedForm::poll(uint64_t address, uint32_t, SimTime) {
    const SimTime event = event_at(address);
    if (event == kNever) unmodelled("poll that nothing ends", address);
    now_ += poll_notice_fs(event > now_ ? event - now_ : 0);
    advance(now_);
    return value(address);
}

void ClosedForm::advance(SimTime t) {
    for (;;) {
        const SimTime next = std::min({line_.pending, line_.board_at, line_.dma_at});
        if (next == kNever || next > t) return;
        if (line_.pending == next) {
            line_.fired = next;
            line_.pending = kNever;
        } else if (line_.board_at == next) {
            line_.board_at = kNever;
            rise(true, next);
        } else {
            line_.dma_at = kNever;
            rise(false, next);
        }
    }
}

// The bus notifies the host one lag after the line rises, unless a
// notification is already on its way (a later one would be dropped for it).
void ClosedForm::rise(bool board, SimTime at) {
    const bool was_high = line_.board_high || line_.dma_high;
    (board ? line_.board_high : line_.dma_high) = true;
    if (!was_high && line_.pending == kNever) line_.pending = at + lag_;
}

SimTime ClosedForm::next_notification(SimTime t) {
    advance(t);
    for (;;) {
        const SimTime next = std::min({line_.pending, line_.board_at, line_.dma_at});
        if (next == kNever) return kNever;  // nothing will come (the driver's timeout finds the event)
        const bool notification = line_.pending == next;
        advance(next);
        if (notification) return next;
    }
}

SimTime ClosedForm::notification_since(SimTime since, SimTime t) {
    advance(t);
    if (line_.fired != kNever && line_.fired >= since && line_.fired != line_.taken) {
        line_.taken = line_.fired;
        return t;
    }
    return next_notification(t);
}

}  // namespace cdvp
