// Test support: a host whose bus takes a fixed time per access, with a plain
// C++ board behind it clocked from that time; PIO only (no DMA engine). Its
// interrupt handler, when it has one, runs `lag` after the board raises its
// line (the end of a segment). It can break a rule of HostPort's contract on
// purpose.
#pragma once

#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "models/board/board_core.h"
#include "platform/driver/host_port.h"

namespace cdvp::testing {

class DirectPort : public HostPort {
public:
    // The rule of platform/driver/host_port.h the port breaks, if any.
    enum class Fault {
        kNone,
        kPicosecondClock,     // its clock keeps picoseconds: each wait rounded to one
        kInterruptTakenAgain  // wait_for_interrupt_since returns at once whenever a handler has run
    };

    static constexpr SimTime kNoInterrupt = std::numeric_limits<SimTime>::max();

    DirectPort(BoardCore& board, SimTime period, SimTime access_time, SimTime lag = kNoInterrupt,
               Fault fault = Fault::kNone)
        : board_(board), period_(period), access_(access_time), lag_(lag), fault_(fault), memory_(1 << 20) {}

    std::string read(uint64_t address, void* data, uint32_t length) override {
        return access(address, static_cast<unsigned char*>(data), length, false);
    }
    std::string write(uint64_t address, const void* data, uint32_t length) override {
        return access(address, static_cast<unsigned char*>(const_cast<void*>(data)), length, true);
    }
    unsigned char* memory(uint64_t address) override { return memory_.data() + address; }
    uint64_t memory_size() const override { return memory_.size(); }
    SimTime now() const override { return now_; }
    void wait(SimTime duration) override {
        now_ += fault_ == Fault::kPicosecondClock ? (duration + 500) / 1000 * 1000 : duration;
        note_handler();
    }
    void wait_for_interrupt(SimTime timeout) override {
        note_handler();
        if (handler_due_ > now_ && handler_due_ - now_ <= timeout) {
            now_ = handler_due_;
        } else {
            now_ += timeout;
        }
        note_handler();
    }
    void wait_for_interrupt_since(SimTime since, SimTime timeout) override {
        note_handler();
        const bool ran = last_handler_ != kNever;
        if (fault_ == Fault::kInterruptTakenAgain && ran) return;
        if (ran && last_handler_ >= since && last_handler_ != taken_) {
            taken_ = last_handler_;
            return;
        }
        wait_for_interrupt(timeout);
    }

private:
    static constexpr SimTime kNever = kNoInterrupt;

    // The handler of the board's last event has run once its time is past.
    void note_handler() {
        if (handler_due_ <= now_) {
            last_handler_ = handler_due_;
            handler_due_ = kNever;
        }
    }
    std::string access(uint64_t address, unsigned char* data, uint32_t length, bool write) {
        if (board_.running()) board_.advance_to((now_ - segment_start_) / period_);
        const uint64_t segments = board_.segments_started();
        std::string error;
        for (uint32_t k = 0; k < length && error.empty(); k += 4) error = word(address + k, data + k, write);
        if (board_.segments_started() != segments) {
            segment_start_ = now_;
            // START or RESUME: the segment ends its edges later, and its handler runs a lag after.
            if (lag_ != kNoInterrupt) handler_due_ = now_ + board_.segment_edges() * period_ + lag_;
        }
        now_ += access_;
        note_handler();
        return error;
    }
    std::string word(uint64_t address, unsigned char* data, bool write) {
        uint32_t value = 0;
        if (write) std::memcpy(&value, data, 4);
        if (address < address_map::kRegistersSize) {
            const auto offset = static_cast<uint32_t>(address);
            if (write) return board_.write_register(offset, value) == RegisterResult::kDone ? "" : "refused";
            if (!board_.read_register(offset, value)) return "unmapped";
        } else if (address >= address_map::kPairBuffer) {
            const uint64_t k = (address - address_map::kPairBuffer) / 4;
            if (write || k / 2 >= board_.buffered_pairs()) return "unmapped";
            const IndexPair& p = board_.buffered_pair(static_cast<uint32_t>(k / 2));
            value = k % 2 == 0 ? p.first : p.second;
        } else {
            const uint64_t offset = address - address_map::kCoordinateBase;
            const auto c = static_cast<Coordinate>(offset / address_map::kWindowSize);
            const auto i = static_cast<uint32_t>(offset % address_map::kWindowSize / 4);
            if (!write) return "write-only here";
            if (board_.write_coordinate(c, i, value) != RegisterResult::kDone) return "refused";
        }
        if (!write) std::memcpy(data, &value, 4);
        return "";
    }

    BoardCore& board_;
    SimTime period_, access_, lag_;
    Fault fault_;
    std::vector<unsigned char> memory_;
    SimTime now_ = 0, segment_start_ = 0;
    SimTime handler_due_ = kNever, last_handler_ = kNever, taken_ = kNever;
};

}  // namespace cdvp::testing
