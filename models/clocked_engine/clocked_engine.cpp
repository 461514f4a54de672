#include "models/clocked_engine/clocked_engine.h"

#include <algorithm>

namespace cdvp {

const ClockedEngine::Slot ClockedEngine::kNoSlot{};

ClockedEngine::ClockedEngine(const BoardConfig& config, uint32_t capacity)
    : config_(config),
      comparison_unit_(config.lanes(), config.compare, config.format),
      collector_(config.collector),
      line_(BlockRam::kReadLatencyCycles + config.compare.latency_cycles) {
    if (config.tiles.tiled()) {
        loader_ = std::make_unique<TileLoader>(config, capacity);
    } else {
        layout_ = config.format.block_ram_layout(capacity);
        memories_.push_back(make_coordinate_memories(config.m, capacity, layout_));
    }
}

uint32_t ClockedEngine::block_rams() const {
    return loader_ ? loader_->block_rams() : block_rams_of(memories_[0], layout_);
}

void ClockedEngine::start(const CoordinateStore& store, uint32_t objects) {
    schedule_ = SweepSchedule(config_.m, config_.tiles, objects);
    walker_.restart();
    if (loader_) {
        // The host's writes went to the SSRAM banks; the first tile loads from slot 0.
        loader_->start(store, objects, schedule_);
        loads_begun_ = 0;
        if (!schedule_.blocks().empty()) loader_->begin(loads_begun_++);
    } else {
        // The host's writes reach every copy of the block RAMs; loading them
        // here is the same, as nothing reads them before the sweep.
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            for (uint32_t i = 0; i < objects; ++i) memories_[0][c].write(i, store[c][i]);
        }
    }
    block_ = 0;
    waiting_ = false;
    collector_.reset();
    for (auto& slot : line_) slot = Slot{};
    head_ = 0;
    end_issued_ = end_seen_ = stalled_ = false;
    pushed_edge_ = 0;
    edges_ = 0;
    history_.start();
    state_ = SweepState::kRunning;
}

void ClockedEngine::resume() {
    history_.resume(edges_);
    collector_.clear_buffer();
    edges_ = 0;
    pushed_edge_ = 0;
    state_ = SweepState::kRunning;
}

void ClockedEngine::abort(uint64_t edges) {
    advance_to(edges);
    collector_.truncate_buffer(counters_after(edges).buffered);
    state_ = SweepState::kIdle;
}

uint64_t ClockedEngine::segment_edges() {
    while (state_ == SweepState::kRunning) step();
    return edges_;
}

bool ClockedEngine::segment_finishes() {
    segment_edges();
    return state_ == SweepState::kDone;
}

void ClockedEngine::advance_to(uint64_t edges) {
    while (state_ == SweepState::kRunning && edges_ < edges) step();
}

SweepCounters ClockedEngine::counters_after(uint64_t edges) {
    advance_to(edges);
    return history_.counters_after(std::min(edges, edges_));
}

uint32_t ClockedEngine::tile_of(bool column) const {
    const auto& blocks = schedule_.blocks();
    if (blocks.empty()) return 0;
    const SweepSchedule::Block& b = blocks[std::min<uint64_t>(block_, blocks.size() - 1)];
    return column ? b.column_tile : b.row_tile;
}

ClockedEngine::Slot ClockedEngine::issue() {
    if (loader_) loader_->land();
    const ScheduleWalker::Slot next =
        loader_ ? walker_.next(loader_->ready_blocks()) : walker_.next(schedule_.blocks().size());
    if (loader_) {
        // A block that starts starts the next block's load, in this slot.
        const auto& blocks = schedule_.blocks();
        while (loads_begun_ < blocks.size() && loads_begun_ <= walker_.blocks_started()) loader_->begin(loads_begun_++);
        loader_->read();
    }
    waiting_ = next.kind == ScheduleWalker::Slot::kWait;
    if (next.kind == ScheduleWalker::Slot::kEnd) {
        if (end_issued_) return Slot{};
        end_issued_ = true;
        Slot end;
        end.kind = Slot::kEnd;
        return end;
    }
    block_ = next.block;
    if (waiting_) return Slot{};  // a bubble: the tile is still loading
    const PortWindow& addresses = next.window;
    last_issue_ = addresses;
    const SweepSchedule::Block& block = schedule_.blocks()[next.block];
    const uint32_t row_base = loader_ ? schedule_.tile_begin(block.row_tile) : 0;
    const uint32_t column_base = loader_ ? schedule_.tile_begin(block.column_tile) : 0;
    CoordinateMemories& columns = loader_ ? loader_->columns(next.block) : memories_[0];
    CoordinateMemories& rows = loader_ ? loader_->rows(block.row_tile) : columns;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        rows[c].clock_read(0, addresses.row - row_base);
        for (uint32_t lane = 0; lane < addresses.valid_lanes; ++lane) {
            columns[c].clock_read(lane + 1, addresses.first_column + lane - column_base);
        }
    }
    // The hit mask is a pure function of the block RAM output registers just
    // loaded, so computing it here and presenting it compare-latency cycles
    // later is the same as computing it in the last compare stage.
    return Slot{Slot::kSweep, addresses, comparison_unit_.evaluate(rows, columns, addresses.valid_lanes)};
}

void ClockedEngine::stall() {
    stalled_ = true;
    history_.stall(edges_);
}

// One clock edge; every edge counts as a cycle. An edge that finds the pair
// buffer full pauses the board (and counts as a stall).
void ClockedEngine::step() {
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
        // beyond S + L, so it counts as a stall.
        stall();
        if (collector_.fifo_level() == 0) state_ = SweepState::kDone;
        return;
    }
    Slot& leaving = line_[head_];
    if (leaving.kind == Slot::kSweep) {
        const auto hits = static_cast<uint32_t>(__builtin_popcountll(leaving.hits));
        if (collector_.fifo_free() < hits) {
            stall();  // back-pressure: the whole pipeline holds this cycle
            return;
        }
        collector_.push(leaving.window.row, leaving.window.first_column, leaving.hits);
        pushed_hits_ = leaving.hits;
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

}  // namespace cdvp
