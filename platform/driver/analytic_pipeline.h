// Frames pipelined on a board with two box banks, timed from closed forms:
// the driver's own submit and finish (driver_sequence.h) on the closed-form
// executor (closed_form.h), which keeps the host's clock and the interrupt
// line from frame to frame. The upload of frame k+1 runs beside the sweep of
// frame k; the host then waits for frame k's end (the part of its sweep the
// upload hid is overlap, not compute), starts frame k+1 and reads frame k's
// last pairs from the previous pair buffer while k+1 sweeps. Each frame
// keeps its own account, so its phases add up to the host's time on it, and
// its latency runs from its upload to its last pair. Estimated, not exact
// (docs/analytic.md measures it): the FIFO stalls as in AnalyticFrame.
#pragma once

#include <cstdint>
#include <optional>

#include "platform/driver/analytic_frame.h"
#include "platform/driver/closed_form.h"
#include "platform/driver/driver_sequence.h"

namespace cdvp {

class AnalyticPipeline {
public:
    // frame must outlive this; it gives the forms and the board.
    explicit AnalyticPipeline(const AnalyticFrame& frame);
    AnalyticPipeline(const AnalyticPipeline&) = delete;
    AnalyticPipeline& operator=(const AnalyticPipeline&) = delete;

    // A frame of `objects` boxes whose sweep finds `pairs` (board order;
    // kept until it finishes), `changed` of its boxes differing from its
    // bank's copy: uploaded and started; the frame before it, finished, when
    // one was in flight: its phases, its pairs swapped into `finished`.
    std::optional<FramePhases> submit(uint32_t objects, PairList&& pairs, uint64_t changed, PairList& finished);
    // The frame in flight, finished the same way; nothing when none is.
    std::optional<FramePhases> finish(PairList& finished);

private:
    // A frame in flight or being submitted: its plan and the pairs it reads.
    struct Slot {
        FramePlan plan;
        PairList pairs;
    };

    const AnalyticFrame& frame_;
    ClosedForm form_;
    DriverSequence<ClosedForm> sequence_;
    ClosedForm::Pairs read_back_;
    Slot slots_[2];
    uint32_t next_ = 0;  // the slot the next frame takes (the other holds the frame in flight)
};

}  // namespace cdvp
