#include "models/fast_engine/sweep_timeline.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "models/address_generator/address_generator.h"
#include "models/block_ram/block_ram.h"
#include "models/common/integer_math.h"

namespace cdvp {

namespace {
constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();
// AddressGenerator::sweep_cycles with one 32-bit division (boxes < 2^32):
// this runs once per hit slot.
uint64_t sweep_cycles32(uint32_t objects, uint32_t lanes) {
    if (objects < 2) return 0;
    const uint32_t q = (objects - 1) / lanes, r = (objects - 1) - q * lanes;
    return uint64_t{lanes} * q * (q + 1) / 2 + uint64_t{r} * (q + 1);
}
}  // namespace

SweepTimeline::SweepTimeline(const BoardConfig& config)
    : lanes_((config.validate(), config.lanes())),
      line_delay_(BlockRam::kReadLatencyCycles + config.compare.latency_cycles),
      fifo_depth_(config.collector.fifo_depth),
      drain_per_cycle_(config.collector.drain_per_cycle),
      buffer_depth_(config.collector.buffer_depth),
      m_(config.m),
      tiles_(config.tiles) {}

void SweepTimeline::start(uint32_t objects, const std::vector<IndexPair>& pairs) {
    objects_ = objects;
    if (tiles_.tiled()) {
        schedule_ = SweepSchedule(m_, tiles_, objects);
        sweep_cycles_ = schedule_.slots();
    } else {
        sweep_cycles_ = AddressGenerator::sweep_cycles(objects, m_);
    }
    pairs_ = &pairs;
    listed_slots_ = nullptr;
    begin();
}

void SweepTimeline::start_listed(const std::vector<IndexPair>& pairs, const std::vector<uint64_t>& slots,
                                 uint64_t end_slot) {
    objects_ = 0;  // not needed: every slot is given
    sweep_cycles_ = end_slot;
    pairs_ = &pairs;
    listed_slots_ = &slots;
    begin();
}

void SweepTimeline::begin() {
    buffer_begin_ = 0;
    Cursor cursor;
    cursor.phase = SweepState::kRunning;
    run_segment(cursor);
}

void SweepTimeline::resume() {
    if (end_.phase != SweepState::kPaused) throw std::logic_error("resume: the sweep is not paused");
    buffer_begin_ += end_.buffer;
    Cursor cursor = end_;
    cursor.buffer = 0;  // the host has read the buffer
    cursor.segment_edges = 0;
    cursor.phase = SweepState::kRunning;
    run_segment(cursor);
}

void SweepTimeline::run_segment(const Cursor& start) {
    checkpoints_.assign(1, start);
    end_ = start;
    if (cannot_pause(start)) {
        if (listed_slots_ == nullptr || start.end_seen || !run_listed_unstalled(end_, checkpoints_)) {
            run_unpaused(end_, checkpoints_);
        }
    } else {
        run(end_, kNever, &checkpoints_);
    }
}

bool SweepTimeline::cannot_pause(const Cursor& start) const {
    return start.fifo + (pairs_->size() - start.next_pair) <= uint64_t{buffer_depth_} - start.buffer;
}

bool SweepTimeline::run_listed_unstalled(Cursor& c, std::vector<Cursor>& checkpoints) const {
    const std::vector<uint64_t>& slots = *listed_slots_;
    const uint64_t n = slots.size();
    const auto drain = static_cast<int64_t>(drain_per_cycle_);
    const Cursor start = c;
    // The state when pair k's slot arrives, the last hit slot having arrived
    // on advance edge `last` and left `fifo` pairs in the FIFO: every
    // advance edge so far, no stall.
    const auto before = [&](uint64_t k, int64_t fifo, int64_t last) {
        Cursor at = start;
        at.advances = static_cast<uint64_t>(last + 1);
        at.segment_edges = start.segment_edges + (at.advances - start.advances);
        at.cycles = start.cycles + (at.advances - start.advances);
        at.total = start.total + (k - start.next_pair);
        at.next_pair = k;
        at.fifo = static_cast<uint32_t>(fifo);
        at.buffer = static_cast<uint32_t>(start.buffer + (at.total - start.total) - (at.fifo - start.fifo));
        at.head.known = false;
        return at;
    };
    // A slot arrives on advance edge slot + D; the edges since the last
    // arrival (the head's own edge included) drain the FIFO, then its hits
    // enter, one pair at a time (no drain between pairs of one slot).
    int64_t fifo = start.fifo;
    int64_t last = static_cast<int64_t>(start.advances) - 1;
    uint32_t until_checkpoint = kCheckpointEvery;  // hit slots
    for (uint64_t k = start.next_pair; k < n; ++k) {
        const auto arrival = static_cast<int64_t>(slots[k] + line_delay_);
        const int64_t edges = arrival - last;
        until_checkpoint -= edges != 0 ? 1 : 0;  // (counted without a branch on it)
        if (until_checkpoint == 0) {
            checkpoints.push_back(before(k, fifo, last));
            until_checkpoint = kCheckpointEvery;
        }
        fifo = std::max<int64_t>(fifo - drain * edges, 0) + 1;
        last = arrival;
        if (fifo > fifo_depth_) {  // back-pressure: the slot waits
            checkpoints.resize(1);
            return false;
        }
    }
    const auto end_arrival = static_cast<int64_t>(sweep_cycles_ + line_delay_);
    if (end_arrival <= last) {
        checkpoints.resize(1);
        return false;
    }
    // The end marker's edge and those before it drain; the FIFO's last pairs
    // then take a stall edge each drain.
    const auto left = static_cast<uint64_t>(std::max<int64_t>(fifo - drain * (end_arrival - last), 0));
    const uint64_t tail = ceil_div(left, drain_per_cycle_);
    c = before(n, 0, end_arrival);
    c.segment_edges += tail;
    c.cycles += tail;
    c.stalls += tail;
    c.buffer = static_cast<uint32_t>(start.buffer + start.fifo + (n - start.next_pair));
    c.end_seen = true;
    c.head = {sweep_cycles_, 0, true};
    c.phase = SweepState::kDone;
    return true;
}

void SweepTimeline::run_unpaused(Cursor& c, std::vector<Cursor>& checkpoints) const {
    // Every pair in the FIFO always finds room in the buffer, so an edge
    // drains min(drain, fifo) and no edge pauses; the buffer holds what
    // entered the FIFO and left it, the cycles count the edges.
    const uint64_t drain = drain_per_cycle_;
    const uint64_t edges0 = c.segment_edges, cycles0 = c.cycles, buffer0 = c.buffer, total0 = c.total, fifo0 = c.fifo;
    uint64_t edges = c.segment_edges, stalls = c.stalls, advances = c.advances, fifo = c.fifo;
    const auto settle = [&] {
        c.segment_edges = edges;
        c.cycles = cycles0 + (edges - edges0);
        c.stalls = stalls;
        c.advances = advances;
        c.fifo = static_cast<uint32_t>(fifo);
        c.buffer = static_cast<uint32_t>(buffer0 + (c.total - total0) - (fifo - fifo0));
    };
    uint32_t slots = 0;
    if (!c.end_seen) {
        for (;;) {
            if (++slots % kCheckpointEvery == 0) {
                settle();
                checkpoints.push_back(c);
            }
            locate_head(c);
            // Empty slots and bubbles up to the head's arrival (advance edge slot + D).
            const uint64_t arrival = c.head.slot + line_delay_;
            if (advances < arrival) {
                const uint64_t k = arrival - advances;
                fifo -= std::min(k * drain, fifo);
                edges += k;
                advances = arrival;
            }
            const uint64_t hits = c.head.hits;
            if (hits == 0) {  // the end marker's edge
                fifo -= std::min(drain, fifo);
                ++edges;
                ++advances;
                c.end_seen = true;
                break;
            }
            if (fifo - std::min(drain, fifo) + hits > fifo_depth_) {
                // Back-pressure: the stall edges until an edge's drain leaves room.
                const uint64_t k = ceil_div(fifo + hits - fifo_depth_, drain) - 1;
                fifo -= std::min(k * drain, fifo);
                edges += k;
                stalls += k;
            }
            // The head's edge: its hits enter the FIFO.
            fifo = fifo - std::min(drain, fifo) + hits;
            ++edges;
            ++advances;
            c.total += hits;
            c.next_pair += hits;
            c.head.known = false;
        }
    }
    // The FIFO's last pairs, a stall edge each drain.
    const uint64_t k = ceil_div(fifo, drain);
    edges += k;
    stalls += k;
    fifo = 0;
    settle();
    c.phase = SweepState::kDone;
}

BoardObservation SweepTimeline::observe(uint64_t edges) const {
    Cursor cursor = end_;
    if (edges < end_.segment_edges) {
        // The last checkpoint at or before `edges`; checkpoints_[0] is at 0.
        auto after = std::upper_bound(checkpoints_.begin(), checkpoints_.end(), edges,
                                      [](uint64_t e, const Cursor& c) { return e < c.segment_edges; });
        cursor = *(after - 1);
        run(cursor, edges, nullptr);
    }
    BoardObservation seen;
    seen.cycles = cursor.cycles;
    seen.stalls = cursor.stalls;
    seen.buffer_count = cursor.buffer;
    seen.total_pairs = cursor.total;
    seen.fifo_level = cursor.fifo;
    seen.phase = cursor.phase;
    return seen;
}

// Fills cursor.head field by field (a returned struct here costs a store-forwarding stall).
void SweepTimeline::locate_head(Cursor& cursor) const {
    const std::vector<IndexPair>& pairs = *pairs_;
    cursor.head.known = true;
    if (cursor.next_pair >= pairs.size()) {  // the end marker
        cursor.head.slot = sweep_cycles_;
        cursor.head.hits = 0;
        return;
    }
    const IndexPair& first = pairs[cursor.next_pair];
    if (tiles_.tiled() || listed_slots_ != nullptr) {
        locate_tiled_head(cursor);
        return;
    }
    const uint32_t row = first.first;
    const uint32_t step = (first.second - row - 1) / lanes_;
    const uint64_t row_start = sweep_cycles_ - sweep_cycles32(objects_ - row, lanes_);
    // The slot's hits: the following pairs of the same row within the same 2m-1 columns.
    const uint64_t last_column = uint64_t{row} + uint64_t{step} * lanes_ + lanes_;
    uint32_t hits = 1;
    for (uint64_t k = cursor.next_pair + 1; k < pairs.size() && pairs[k].first == row && pairs[k].second <= last_column; ++k) {
        ++hits;
    }
    cursor.head.slot = row_start + step;
    cursor.head.hits = hits;
}

// Out of line, so that the untiled path above stays as it was.
__attribute__((noinline)) void SweepTimeline::locate_tiled_head(Cursor& cursor) const {
    const std::vector<IndexPair>& pairs = *pairs_;
    if (listed_slots_ != nullptr) {
        // The slot's hits: the following pairs given the same slot.
        const std::vector<uint64_t>& slots = *listed_slots_;
        const uint64_t slot = slots[cursor.next_pair];
        uint64_t end = cursor.next_pair + 1;
        while (end < slots.size() && slots[end] == slot) ++end;
        cursor.head.slot = slot;
        cursor.head.hits = static_cast<uint32_t>(end - cursor.next_pair);
        return;
    }
    const IndexPair& first = pairs[cursor.next_pair];
    // The slot's hits: the following pairs the same slot compares.
    const uint64_t slot = schedule_.pair_slot(first.first, first.second);
    uint32_t hits = 1;
    for (uint64_t k = cursor.next_pair + 1;
         k < pairs.size() && pairs[k].first == first.first && schedule_.pair_slot(first.first, pairs[k].second) == slot;
         ++k) {
        ++hits;
    }
    cursor.head.slot = slot;
    cursor.head.hits = hits;
}

void SweepTimeline::drain_edges(Cursor& cursor, uint64_t k, uint32_t stall_per_edge) const {
    const uint64_t room = buffer_depth_ - cursor.buffer;
    const auto moved = static_cast<uint32_t>(std::min<uint64_t>({k * drain_per_cycle_, cursor.fifo, room}));
    cursor.fifo -= moved;
    cursor.buffer += moved;
    cursor.segment_edges += k;
    cursor.cycles += k;
    cursor.stalls += k * stall_per_edge;
    if (stall_per_edge == 0) cursor.advances += k;
}

void SweepTimeline::run(Cursor& c, uint64_t limit, std::vector<Cursor>* checkpoints) const {
    const uint32_t drain = drain_per_cycle_;
    uint32_t events = 0;
    // Every pass runs at least one edge.
    while (c.phase == SweepState::kRunning && c.segment_edges < limit) {
        if (checkpoints != nullptr && ++events % kCheckpointEvery == 0) checkpoints->push_back(c);
        uint64_t budget = limit - c.segment_edges;
        uint32_t room = buffer_depth_ - c.buffer;
        if (c.fifo > 0 && room == 0) {
            // A pair must move and the buffer is full: this edge pauses.
            ++c.segment_edges;
            ++c.cycles;
            ++c.stalls;
            c.phase = SweepState::kPaused;
            continue;
        }
        // Edges until the buffer fills with pairs still in the FIFO (the next one pauses).
        uint64_t until_full = c.fifo > room ? ceil_div(room, drain) : kNever;
        if (c.end_seen) {  // only the FIFO's last pairs are left: each edge is a stall
            drain_edges(c, std::min({ceil_div(c.fifo, drain), until_full, budget}), 1);
            if (c.fifo == 0) c.phase = SweepState::kDone;
            continue;
        }
        if (!c.head.known) locate_head(c);
        const HeadSlot& head = c.head;
        // Slot s reaches the collector on advance edge s + 1 + D.
        const uint64_t arrival = head.slot + line_delay_;
        if (c.advances < arrival) {  // empty slots and bubbles before it
            drain_edges(c, std::min({arrival - c.advances, until_full, budget}), 0);
            // Arrived with edges left and no pause due: the head's edge follows
            // in this pass (the loop's checks, redone for the new state).
            room = buffer_depth_ - c.buffer;
            if (c.advances < arrival || c.segment_edges >= limit || (c.fifo > 0 && room == 0)) continue;
            until_full = c.fifo > room ? ceil_div(room, drain) : kNever;
            budget = limit - c.segment_edges;
        }
        const uint32_t moved = std::min({drain, c.fifo, room});
        if (head.hits == 0) {  // the end marker
            drain_edges(c, 1, 0);
            c.end_seen = true;
            if (c.fifo == 0) c.phase = SweepState::kDone;
            continue;
        }
        if (c.fifo - moved + head.hits <= fifo_depth_) {  // the slot's hits enter the FIFO
            drain_edges(c, 1, 0);
            c.fifo += head.hits;
            c.total += head.hits;
            c.next_pair += head.hits;
            c.head.known = false;
            continue;
        }
        // Back-pressure: stall until an edge's drain leaves room, i.e. the
        // first edge k with min(k * drain, fifo, room) >= need, or until the
        // buffer fills first.
        const uint64_t need = c.fifo + head.hits - fifo_depth_;
        const uint64_t stall_edges = need <= room ? ceil_div(need, drain) - 1 : until_full;
        drain_edges(c, std::min(stall_edges, budget), 1);
    }
}

}  // namespace cdvp
