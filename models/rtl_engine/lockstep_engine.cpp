#include "models/rtl_engine/lockstep_engine.h"

#include <algorithm>
#include <sstream>

#include "models/clocked_engine/clocked_engine.h"
#include "models/grid_clocked_engine/grid_clocked_engine.h"

namespace cdvp {

namespace {
SweepState state_of(uint8_t rtl_state) {
    if (rtl_state & RtlProbes::kPaused) return SweepState::kPaused;
    if (rtl_state & RtlProbes::kDone) return SweepState::kDone;
    if (rtl_state & (RtlProbes::kSweep | RtlProbes::kDrain)) return SweepState::kRunning;
    return SweepState::kIdle;
}
uint64_t lane_mask(uint32_t lanes) { return lanes >= 64 ? ~uint64_t{0} : (uint64_t{1} << lanes) - 1; }

// Either board's clocked engine: both issue slots of the same shape.
template <class Clocked>
class ClockedModel final : public LockstepModel {
public:
    ClockedModel(const BoardConfig& config, uint32_t capacity) : clocked_(config, capacity) {}
    BoardEngine& engine() override { return clocked_; }
    void advance_to(uint64_t edges) override { clocked_.advance_to(edges); }
    uint64_t edges() const override { return clocked_.edges(); }
    SweepState state() const override { return clocked_.state(); }
    std::optional<PortWindow> issued_window() const override {
        const auto& slot = clocked_.issued();
        if (slot.kind != Clocked::Slot::kSweep) return std::nullopt;
        return slot.window;
    }
    uint64_t pushed_hits() const override { return clocked_.pushed_hits(); }
    uint32_t fifo_level() const override { return clocked_.fifo_level(); }

private:
    Clocked clocked_;
};

std::unique_ptr<LockstepModel> clocked_model(const BoardConfig& config, uint32_t capacity) {
    if (config.grid_board()) return std::make_unique<ClockedModel<GridClockedEngine>>(config, capacity);
    return std::make_unique<ClockedModel<ClockedEngine>>(config, capacity);
}
}  // namespace

// The RTL first: a board it cannot run is refused before the model is built.
LockstepEngine::LockstepEngine(const BoardConfig& model, const BoardConfig& rtl, uint32_t capacity)
    : rtl_(rtl, capacity) {
    clocked_ = clocked_model(model, capacity);
}

LockstepEngine::~LockstepEngine() = default;

void LockstepEngine::start(const CoordinateStore& store, uint32_t objects) {
    first_.reset();  // each frame is compared afresh
    clocked_->engine().start(store, objects);
    rtl_.start(store, objects);
    cycle_at_segment_start_ = 0;
}

void LockstepEngine::resume() {
    cycle_at_segment_start_ = rtl_.probes().cycles;
    if (!first_) clocked_->engine().resume();
    rtl_.resume();
}

void LockstepEngine::abort(uint64_t edges) {
    advance_to(edges);
    if (!first_) clocked_->engine().abort(edges);
    rtl_.abort(edges);
}

bool LockstepEngine::running() const {
    return rtl_.state() == SweepState::kRunning || (!first_ && clocked_->state() == SweepState::kRunning);
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
    const uint64_t edge = std::max(clocked_->edges(), rtl_.edges()) + 1;
    clocked_->advance_to(edge);
    rtl_.advance_to(edge);
    ++compared_;
    compare_edge(before);
}

void LockstepEngine::diverge(const std::string& signal, uint64_t rtl, uint64_t model) {
    const uint64_t edge = std::max(clocked_->edges(), rtl_.edges());
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
    BoardEngine& engine = clocked_->engine();
    const SweepCounters model = engine.counters_after(edge);
    // The slot this edge issued: port 0's box, port 1's box, the lanes with a box.
    const std::optional<PortWindow> issued = clocked_->issued_window();
    const bool rtl_window = before.enable && before.window;
    check("address_issued", rtl_window, issued.has_value());
    if (issued) {
        check("address_row (port 0)", before.row, issued->row);
        check("address_column (port 1)", before.first_column, issued->first_column);
        check("lane_valid", before.valid_lanes, lane_mask(issued->valid_lanes));
    }
    // The lane hits this edge pushed into the pair FIFO.
    check("lane_hits_pushed", before.enable ? before.hits : 0, clocked_->pushed_hits());
    // Then what the edge left: the FIFO, the pair buffer, the counters and the state.
    check("fifo_level", rtl.fifo_level, clocked_->fifo_level());
    if (rtl.pair_valid && model.buffered > 0) {
        const IndexPair& pair = engine.buffer_entry(model.buffered - 1);
        check("pair_row", rtl.pair.first, pair.first);
        check("pair_column", rtl.pair.second, pair.second);
    }
    check("PAIR_COUNT", rtl.buffered, model.buffered);
    check("TOTAL_PAIRS", rtl.total_pairs, model.total_pairs);
    check("STALLS", rtl.stalls, model.stalls);
    check("CYCLES", rtl.cycles, model.cycles);
    check("state (0 idle, 1 running, 2 paused, 3 done)", static_cast<uint64_t>(state_of(rtl.state)),
          static_cast<uint64_t>(clocked_->state()));
    if (!first_ && clocked_->state() == SweepState::kDone) compare_grid_registers();
}

// A grid board's last-sweep registers, once the sweep is done (an all-pairs
// board's are all zero on both sides).
void LockstepEngine::compare_grid_registers() {
    const GridSweepStats rtl = rtl_.grid_stats();
    const GridSweepStats model = clocked_->engine().grid_stats();
    auto check = [this](const char* signal, uint64_t in_rtl, uint64_t in_model) {
        if (!first_ && in_rtl != in_model) diverge(signal, in_rtl, in_model);
    };
    check("GRID_SWEEP_DIMS", rtl.dims, model.dims);
    check("GRID_LARGE_BOXES", rtl.large_boxes, model.large_boxes);
    check("GRID_OVERFLOW_BOXES", rtl.overflow_boxes, model.overflow_boxes);
    check("GRID_CELL_ENTRIES", rtl.cell_entries, model.cell_entries);
    check("GRID_BUSY_CELLS", rtl.busy_cells, model.busy_cells);
    check("GRID_EXCLUDED_BOXES", rtl.excluded_boxes, model.excluded_boxes);
    check("the sweep's slots", rtl.slots, model.slots);
}

}  // namespace cdvp
