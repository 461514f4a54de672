// The back end both clocked engines share (the seed's board and the grid
// board): the slots the front end issues travel the block RAM and compare
// stages to the pair collector, one clock edge at a time, with back-pressure,
// the end-of-sweep drain and the overflow pause; what each edge showed the
// host is kept (SegmentHistory), so a segment stepped ahead answers for any
// earlier edge.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "models/board_spec/board_engine.h"
#include "models/board_spec/segment_history.h"
#include "models/pair_collector/pair_collector.h"

namespace cdvp {

// Slot: a default-constructed bubble with `kind` (Slot::kBubble, kSweep,
// kEnd) and hit_count(), the pairs it pushes.
template <class Slot>
class SlotPipeline {
public:
    SlotPipeline(uint32_t stages, const PairCollectorConfig& collector) : collector_(collector), line_(stages) {}

    // START: an empty pipeline and collector, counters from zero.
    void start() {
        collector_.reset();
        for (auto& slot : line_) slot = Slot{};
        head_ = 0;
        end_seen_ = stalled_ = false;
        pushed_edge_ = 0;
        edges_ = 0;
        history_.start();
        state_ = SweepState::kRunning;
    }
    // RESUME after an overflow pause: the host has read the buffer.
    void resume() {
        history_.resume(edges_);
        collector_.clear_buffer();
        edges_ = 0;
        pushed_edge_ = 0;
        state_ = SweepState::kRunning;
    }
    // ABORT once stepped to the abort's edge: the buffer keeps what it held then.
    void abort(uint64_t edges) {
        collector_.truncate_buffer(counters_after(edges).buffered);
        state_ = SweepState::kIdle;
    }

    // One clock edge; every edge counts as a cycle. issue() gives the slot
    // entering the pipeline; push(collector, slot) pushes the hits of the
    // slot reaching the collector. An edge that finds the pair buffer full
    // pauses the board (and counts as a stall).
    template <class Issue, class Push>
    void step(Issue&& issue, Push&& push) {
        ++edges_;
        if (collector_.drain_blocked()) {
            // A pair must move and the buffer is full: this edge does no work
            // (a stall) and the clock stops until the host drains and resumes.
            stall();
            state_ = SweepState::kPaused;
            return;
        }
        const uint32_t before = collector_.buffer_count();
        collector_.drain();
        history_.buffered(edges_, collector_.buffer_count() - before);
        if (end_seen_) {
            // Only the FIFO's last pairs are left to move: every such cycle is
            // beyond the slots + L, so it counts as a stall.
            stall();
            if (collector_.fifo_level() == 0) state_ = SweepState::kDone;
            return;
        }
        Slot& leaving = line_[head_];
        if (leaving.kind == Slot::kSweep) {
            const uint32_t hits = leaving.hit_count();
            if (collector_.fifo_free() < hits) {
                stall();  // back-pressure: the whole pipeline holds this cycle
                return;
            }
            push(collector_, static_cast<const Slot&>(leaving));
            pushed_edge_ = edges_;
            history_.pushed(edges_, hits);
        } else if (leaving.kind == Slot::kEnd) {
            end_seen_ = true;
        }
        stalled_ = false;
        leaving = issue();
        head_ = head_ + 1 == line_.size() ? 0 : head_ + 1;
        if (end_seen_ && collector_.fifo_level() == 0) state_ = SweepState::kDone;
    }

    SweepState state() const { return state_; }
    uint64_t edges() const { return edges_; }
    bool stalled() const { return stalled_; }
    bool pushed_this_edge() const { return pushed_edge_ == edges_ && edges_ != 0; }
    // The slot leaving the compare stages at the next edge.
    const Slot& compare_output() const { return line_[head_]; }
    // The slot the last edge issued, or null when it issued none (a stall).
    const Slot* issued() const {
        if (stalled_ || edges_ == 0) return nullptr;
        return &line_[head_ == 0 ? line_.size() - 1 : head_ - 1];
    }
    SweepCounters counters_after(uint64_t edges) const { return history_.counters_after(std::min(edges, edges_)); }
    const PairCollector& collector() const { return collector_; }

private:
    void stall() {
        stalled_ = true;
        history_.stall(edges_);
    }

    PairCollector collector_;
    // Block RAM stage plus compare stages; head_ is the slot leaving this cycle.
    std::vector<Slot> line_;
    uint32_t head_ = 0;
    bool end_seen_ = false;  // the end marker reached the collector
    bool stalled_ = false;
    uint64_t pushed_edge_ = 0;  // the edge of the segment that last pushed (0: none yet)
    SweepState state_ = SweepState::kIdle;
    // The segment so far: edges run, and what each showed the host.
    uint64_t edges_ = 0;
    SegmentHistory history_;
};

}  // namespace cdvp
