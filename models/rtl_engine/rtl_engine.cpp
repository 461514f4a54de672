#include "models/rtl_engine/rtl_engine.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "models/control_registers/control_registers.h"

namespace cdvp {

using R = ControlRegisters;

RtlEngine::RtlEngine(const BoardConfig& config, uint32_t capacity) : config_(config) {
    const BuiltRtlVariant& built = rtl_variant_for(config, capacity);
    variant_ = built.variant;
    board_ = built.make();
    period_fs_ = static_cast<uint64_t>(config.period_ps() * 1000 + 0.5);
    for (auto& words : loaded_) words.assign(capacity, kUnknown);
}

RtlEngine::~RtlEngine() = default;

void RtlEngine::trace_to(const std::string& path, std::function<uint64_t()> command_time_fs) {
    command_time_fs_ = std::move(command_time_fs);
    board_->trace_to(path, period_fs_);
}

void RtlEngine::upload(const CoordinateStore& store, uint32_t objects) {
    // Only the words that differ from what the RTL holds: a delta upload's
    // untouched boxes, and the unchanged boxes of a full one, cost no clock.
    struct Word {
        uint32_t coordinate, index, value;
    };
    std::vector<Word> words;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        for (uint32_t i = 0; i < objects; ++i) {
            if (loaded_[c][i] != store[c][i]) words.push_back({c, i, store[c][i]});
        }
    }
    if (variant_.memory().has_ssram()) {
        for (const Word& w : words) board_->load_ssram(w.coordinate, w.index, w.value);
    } else {
        // The host's writes come before START: place them on the edges just before it.
        if (command_time_fs_) {
            const uint64_t now = command_time_fs_();
            const uint64_t lead = words.size() * period_fs_;
            board_->set_time_fs(now > lead ? now - lead : 0);
        }
        for (const Word& w : words) {
            board_->write(static_cast<uint32_t>(address_map::kCoordinateBase + w.coordinate * address_map::kWindowSize +
                                                4ull * w.index),
                          w.value);
        }
    }
    for (const Word& w : words) loaded_[w.coordinate][w.index] = w.value;
}

GridSweepStats RtlEngine::grid_stats() const {
    if (!variant_.grid) return {};
    GridSweepStats stats;
    stats.dims = probes_.grid_dims;
    stats.large_boxes = probes_.grid_large;
    stats.overflow_boxes = probes_.grid_overflow;
    stats.excluded_boxes = probes_.grid_excluded;
    stats.cell_entries = probes_.grid_entries;
    stats.busy_cells = probes_.grid_busy;
    stats.slots = probes_.grid_slots;
    return stats;
}

void RtlEngine::command(uint32_t control) {
    if (command_time_fs_) board_->set_time_fs(command_time_fs_());
    board_->write(R::kControl, control);
    probes_ = board_->probes();
}

void RtlEngine::start(const CoordinateStore& store, uint32_t objects) {
    if (state_ == SweepState::kRunning || state_ == SweepState::kPaused) command(R::kAbort);
    upload(store, objects);
    board_->write(R::kObjectCount, objects);
    command(R::kStart);
    if ((probes_.state & (RtlProbes::kSweep | RtlProbes::kDrain)) == 0) {
        throw std::logic_error("the board RTL did not take START (state " + std::to_string(probes_.state) + ")");
    }
    edges_ = 0;
    history_.start();
    pairs_.clear();
    state_ = SweepState::kRunning;
}

void RtlEngine::resume() {
    history_.resume(edges_);
    command(R::kResume);
    if ((probes_.state & (RtlProbes::kSweep | RtlProbes::kDrain)) == 0) {
        throw std::logic_error("the board RTL did not take RESUME (state " + std::to_string(probes_.state) + ")");
    }
    edges_ = 0;
    pairs_.clear();
    state_ = SweepState::kRunning;
}

void RtlEngine::abort(uint64_t edges) {
    advance_to(edges);
    pairs_.resize(counters_after(edges).buffered);
    command(R::kAbort);
    state_ = SweepState::kIdle;
}

uint64_t RtlEngine::segment_edges() {
    while (state_ == SweepState::kRunning) step();
    return edges_;
}

bool RtlEngine::segment_finishes() {
    segment_edges();
    return state_ == SweepState::kDone;
}

void RtlEngine::advance_to(uint64_t edges) {
    while (state_ == SweepState::kRunning && edges_ < edges) step();
}

SweepCounters RtlEngine::counters_after(uint64_t edges) {
    advance_to(edges);
    return history_.counters_after(std::min(edges, edges_));
}

void RtlEngine::step() {
    ++edges_;
    board_->edge();
    const RtlProbes now = board_->probes();
    if (now.stalls != probes_.stalls) history_.stall(edges_);
    if (now.total_pairs != probes_.total_pairs) history_.pushed(edges_, now.total_pairs - probes_.total_pairs);
    if (now.pair_valid) {
        pairs_.push_back(now.pair);
        history_.buffered(edges_);
    }
    probes_ = now;
    if (now.state & RtlProbes::kPaused) {
        state_ = SweepState::kPaused;
    } else if (now.state & RtlProbes::kDone) {
        state_ = SweepState::kDone;
    } else if ((now.state & (RtlProbes::kSweep | RtlProbes::kDrain)) == 0) {
        throw std::logic_error("the board RTL left its sweep without a pause or done (state " +
                               std::to_string(now.state) + ")");
    }
}

}  // namespace cdvp
