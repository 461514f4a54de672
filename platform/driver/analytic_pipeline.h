// Frames pipelined on a board with two box banks, timed from closed forms:
// the host's timeline as BoardDriver::submit and finish walk it, each step
// priced by AnalyticFrame's forms. The upload of frame k+1 runs beside the
// sweep of frame k; the host then waits for frame k's end (the part of its
// sweep the upload hid is overlap, not compute), starts frame k+1 and reads
// frame k's last pairs from the previous pair buffer while k+1 sweeps. Each
// frame keeps its own account, so its phases add up to the host's time on
// it, and its latency runs from its upload to its last pair.
//
// With a sweep beside the host, its interrupt shares the line with the
// host's DMAs: the waits follow the line as the platform drives it (the
// board's and the DMA's requests ORed; a rising edge notifies the host one
// interrupt lag later unless a notification is still on its way; the driver
// acknowledges the board before a DMA wait, and looks again when woken by
// the board). Estimated, not exact (docs/analytic.md measures it): the FIFO
// stalls as in AnalyticFrame, and with pauses the segments' lengths.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "platform/driver/analytic_frame.h"

namespace cdvp {

class AnalyticPipeline {
public:
    // frame must outlive this; it gives the forms and the board.
    explicit AnalyticPipeline(const AnalyticFrame& frame);

    // A frame of `objects` boxes whose sweep finds `pairs` (board order),
    // `changed` of its boxes differing from its bank's copy: uploaded and
    // started; the frame before it, finished, when one was in flight.
    std::optional<FramePhases> submit(uint32_t objects, const PairList& pairs, uint64_t changed);
    // The frame in flight, finished; nothing when none is.
    std::optional<FramePhases> finish();

private:
    enum Phase { kUpload, kStart, kCompute, kIrq, kReadback, kDriver, kPhases };
    struct Flight {
        uint32_t objects = 0;
        AnalyticFrame::SweepPlan sweep;
        std::vector<uint64_t> words;  // each segment's pairs' words
        SimTime began = 0, segment_start = 0;
        SimTime spent[kPhases] = {};
        FramePhases phases;
    };
    static constexpr SimTime kNever = std::numeric_limits<SimTime>::max();
    // The interrupt line: the board's and the DMA's requests, the
    // notification on its way to the host, the last one that came.
    struct Line {
        SimTime board_at = kNever, dma_at = kNever;  // requests yet to rise
        bool board_high = false, dma_high = false;
        SimTime pending = kNever, fired = kNever, taken = kNever;
    };

    // Waits for each segment of `f` but (with defer_last) the last one's
    // pairs: paused segments read back and resumed.
    void finish_sweep(Flight& f, bool defer_last);
    // One segment's PAIR_COUNT, PAIR_WORDS and pairs, and the host's work on them.
    void read_pairs(Flight& f, uint64_t segment);
    void show_pair_bank(bool previous, Flight& f);
    FramePhases close(Flight& f) const;
    void spend(Flight& f, Phase phase, SimTime fs) {
        f.spent[phase] += fs;
        now_ += fs;
    }
    // A DMA of `setup` register writes and `transfer` on the bus, from now:
    // its wait (by interrupt or polling) and the write that clears it; the
    // time it took.
    SimTime dma(uint32_t setup, SimTime transfer);
    // The line's events up to `t`, in time order (a notification due at the
    // same time as a rise comes first).
    void advance(SimTime t);
    void rise(bool board, SimTime at);
    // The time the next notification reaches a host waiting from `t`; kNever
    // when none will.
    SimTime next_notification(SimTime t);
    // HostPort::wait_for_interrupt_since: at once for a notification since
    // `since` not taken yet, else the next one.
    SimTime notification_since(SimTime since, SimTime t);

    const AnalyticFrame& frame_;
    SimTime read_, write_, lag_;
    SimTime now_ = 0;
    Line line_;
    std::optional<Flight> in_flight_;
    bool showing_previous_ = false;  // PAIR_BANK: the previous sweep's buffer
};

}  // namespace cdvp
