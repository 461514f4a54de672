// Frames pipelined on a board with two box banks, timed from closed forms:
// the host's timeline as BoardDriver::submit and finish walk it, each step
// priced by AnalyticFrame's forms. The upload of frame k+1 runs beside the
// sweep of frame k; the host then waits for frame k's end (the part of its
// sweep the upload hid is overlap, not compute), starts frame k+1 and reads
// frame k's last pairs from the previous pair buffer while k+1 sweeps. Each
// frame keeps its own account, so its phases add up to the host's time on
// it, and its latency runs from its upload to its last pair.
//
// Estimated, not exact (docs/analytic.md measures it): the FIFO stalls as in
// AnalyticFrame, and with pauses the segments' lengths (spread evenly), which
// decide how much of a sweep the host's upload hides.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "platform/driver/analytic_frame.h"

namespace cdvp {

class AnalyticPipeline {
public:
    // frame must outlive this; it gives the forms and the board.
    explicit AnalyticPipeline(const AnalyticFrame& frame) : frame_(frame) {}

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
        std::vector<uint64_t> counts, words;  // each segment's pairs and their words
        uint64_t cycles = 0;
        SimTime began = 0, segment_start = 0;
        SimTime spent[kPhases] = {};
        FramePhases phases;
    };
    // Waits for each segment of `f` but (with defer_last) the last one's
    // pairs: paused segments read back and resumed.
    void finish_sweep(Flight& f, bool defer_last);
    // One segment's PAIR_COUNT, PAIR_WORDS and pairs, and the host's work on them.
    void read_pairs(Flight& f, uint64_t segment);
    void show_pair_bank(bool previous, Flight& f);
    FramePhases close(Flight& f) const;
    // When the flight's sweep first raises the board's interrupt (its first segment's end).
    SimTime first_event(const Flight& f) const;
    // Where a DMA wait under interrupts beside a running sweep ends (its
    // status read returned), from its start, the transfer's time and the
    // sweep's event.
    SimTime dma_wait_beside(SimTime wait_from, SimTime transfer, SimTime board_event) const;
    void spend(Flight& f, Phase phase, SimTime fs) {
        f.spent[phase] += fs;
        now_ += fs;
    }

    const AnalyticFrame& frame_;
    SimTime now_ = 0;
    std::optional<Flight> in_flight_;
    bool showing_previous_ = false;  // PAIR_BANK: the previous sweep's buffer
};

}  // namespace cdvp
