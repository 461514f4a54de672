#include "models/rtl_engine/lockstep_engine.h"

#include <algorithm>
#include <sstream>

namespace cdvp {

namespace {
SweepState state_of(uint8_t rtl_state) {
    if (rtl_state & RtlProbes::kPaused) return SweepState::kPaused;
    if (rtl_state & RtlProbes::kDone) return SweepState::kDone;
    if (rtl_state & (RtlProbes::kSweep | RtlProbes::kDrain)) return SweepState::kRunning;
    return SweepState::kIdle;
}
uint64_t lane_mask(uint32_t lanes) { return lanes >= 64 ? ~uint64_t{0} : (uint64_t{1} << lanes) - 1; }
}  // namespace

LockstepEngine::LockstepEngine(const BoardConfig& model, const BoardConfig& rtl, uint32_t capacity)
    : clocked_(model, capacity), rtl_(rtl, capacity) {}

void LockstepEngine::start(const CoordinateStore& store, uint32_t objects) {
    first_.reset();  // each frame is compared afresh
    clocked_.start(store, objects);
    rtl_.start(store, objects);
    cycle_at_segment_start_ = 0;
}

void LockstepEngine::resume() {
    cycle_at_segment_start_ = rtl_.probes().cycles;
    if (!first_) clocked_.resume();
    rtl_.resume();
}

void LockstepEngine::abort(uint64_t edges) {
    advance_to(edges);
    if (!first_) clocked_.abort(edges);
    rtl_.abort(edges);
}

bool LockstepEngine::running() const {
    return rtl_.state() == SweepState::kRunning || (!first_ && clocked_.state() == SweepState::kRunning);
}

uint64_t LockstepEngine::segment_edges() {
    while (running()) step();
    return rtl_.edges();
}

bool LockstepEngine::ended_by(uint64_t edges) {
    advance_to(edges);
    return rtl_.ended_by(edges);
}

bool LockstepEngine::segment_finishes() {
    segment_edges();
    return rtl_.segment_finishes();
}

SweepCounters LockstepEngine::counters_after(uint64_t edges) {
    advance_to(edges);
    return rtl_.counters_after(edges);
}

void LockstepEngine::advance_to(uint64_t edges) {
    while (rtl_.edges() < edges && running()) step();
}

void LockstepEngine::step() {
    if (first_) {  // the models parted: the RTL goes on alone
        rtl_.advance_to(rtl_.edges() + 1);
        return;
    }
    const RtlProbes before = rtl_.probes();
    const uint64_t edge = std::max(clocked_.edges(), rtl_.edges()) + 1;
    clocked_.advance_to(edge);
    rtl_.advance_to(edge);
    ++compared_;
    compare_edge(before);
}

void LockstepEngine::diverge(const std::string& signal, uint64_t rtl, uint64_t model) {
    const uint64_t edge = std::max(clocked_.edges(), rtl_.edges());
    const uint64_t cycle = cycle_at_segment_start_ + edge;
    std::ostringstream what;
    what << "lockstep: the RTL and the clocked model differ at sweep cycle " << cycle << " (edge " << edge
         << " of the segment): " << signal << " is " << rtl << " in the RTL, " << model << " in the model";
    first_.emplace(cycle, signal, what.str());
}

// In pipeline order, so the first signal named is nearest the cause.
// `before`: the RTL's signals before this edge, which decide what the edge
// does (a slot issued when the pipeline was enabled, the hits it pushed).
void LockstepEngine::compare_edge(const RtlProbes& before) {
    const RtlProbes& rtl = rtl_.probes();
    const uint64_t edge = rtl_.edges();
    // The first signal that differs is the one named.
    auto check = [this](const char* signal, uint64_t in_rtl, uint64_t in_model) {
        if (!first_ && in_rtl != in_model) diverge(signal, in_rtl, in_model);
    };
    const SweepCounters model = clocked_.counters_after(edge);
    // The slot this edge issued: port 0's box, port 1's box, the lanes with a box.
    const ClockedEngine::Slot& issued = clocked_.issued();
    const bool model_window = issued.kind == ClockedEngine::Slot::kSweep;
    const bool rtl_window = before.enable && before.window;
    check("address_issued", rtl_window, model_window);
    if (model_window) {
        check("address_row (port 0)", before.row, issued.window.row);
        check("address_column (port 1)", before.first_column, issued.window.first_column);
        check("lane_valid", before.valid_lanes, lane_mask(issued.window.valid_lanes));
    }
    // The lane hits this edge pushed into the pair FIFO.
    check("lane_hits_pushed", before.enable ? before.hits : 0, clocked_.pushed_hits());
    // Then what the edge left: the FIFO, the pair buffer, the counters and the state.
    check("fifo_level", rtl.fifo_level, clocked_.fifo_level());
    if (rtl.pair_valid && model.buffered > 0) {
        const IndexPair& pair = clocked_.buffer_entry(model.buffered - 1);
        check("pair_row", rtl.pair.first, pair.first);
        check("pair_column", rtl.pair.second, pair.second);
    }
    check("PAIR_COUNT", rtl.buffered, model.buffered);
    check("TOTAL_PAIRS", rtl.total_pairs, model.total_pairs);
    check("STALLS", rtl.stalls, model.stalls);
    check("CYCLES", rtl.cycles, model.cycles);
    check("state (0 idle, 1 running, 2 paused, 3 done)", static_cast<uint64_t>(state_of(rtl.state)),
          static_cast<uint64_t>(clocked_.state()));
}

}  // namespace cdvp
