// Frames pipelined on a board with two box banks: the host uploads frame k+1
// into one bank while the board sweeps frame k in the other, and reads frame
// k's pairs back from the previous pair buffer while frame k+1 sweeps
// (docs/communication.md). Each frame keeps its own account of the host's
// time, so a frame's phases add up to the host's time on it and the frames'
// totals to the run's simulated time; its latency spans two calls.
#include <stdexcept>
#include <string>

#include "models/control_registers/control_registers.h"
#include "platform/driver/board_driver.h"

namespace cdvp {

using R = ControlRegisters;

bool BoardDriver::submit(const std::vector<FloatBox>& boxes, PairList& pairs, FramePhases& phases) {
    if (!pipelined()) throw std::logic_error("submit: the board has one box bank; use run_frame");
    check_capacity(boxes);
    try {
        FrameAccount next;
        open_account(next, static_cast<uint32_t>(boxes.size()));
        // Into the host's bank while the board sweeps the frame in flight.
        upload(boxes);
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
            check_found(found, in_flight_pairs_);
            phases = close_account(*in_flight_, true);
            pairs.swap(in_flight_pairs_);
        }
        in_flight_ = next;
        account_ = &*in_flight_;
        in_flight_pairs_.clear();
        return finishing;
    } catch (const std::exception&) {
        fail_frames(pairs);
        throw;
    }
}

bool BoardDriver::finish(PairList& pairs, FramePhases& phases) {
    if (!in_flight_) return false;
    try {
        account_ = &*in_flight_;
        mark_ = port_.now();
        const uint64_t found = finish_sweep(*in_flight_, in_flight_pairs_, true, false);
        charge(kReadback);
        check_found(found, in_flight_pairs_);
        phases = close_account(*in_flight_, true);
        pairs.swap(in_flight_pairs_);
        in_flight_.reset();
        in_flight_pairs_.clear();
        return true;
    } catch (const std::exception&) {
        fail_frames(pairs);
        throw;
    }
}

}  // namespace cdvp
