#include "models/clocked_engine/clocked_engine.h"

#include <algorithm>

namespace cdvp {

const ClockedEngine::Slot ClockedEngine::kNoSlot{};

ClockedEngine::ClockedEngine(const BoardConfig& config, uint32_t capacity)
    : config_(config),
      comparison_unit_(config.lanes(), config.compare, config.format),
      pipeline_(BlockRam::kReadLatencyCycles + config.compare.latency_cycles, config.collector) {
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
    end_issued_ = false;
    pipeline_.start();
}

void ClockedEngine::resume() { pipeline_.resume(); }

void ClockedEngine::abort(uint64_t edges) {
    advance_to(edges);
    pipeline_.abort(edges);
}

uint64_t ClockedEngine::segment_edges() {
    while (state() == SweepState::kRunning) step();
    return edges();
}

bool ClockedEngine::segment_finishes() {
    segment_edges();
    return state() == SweepState::kDone;
}

void ClockedEngine::advance_to(uint64_t edges) {
    while (state() == SweepState::kRunning && this->edges() < edges) step();
}

SweepCounters ClockedEngine::counters_after(uint64_t edges) {
    advance_to(edges);
    return pipeline_.counters_after(edges);
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

// One clock edge of the pipeline and collector (SlotPipeline).
void ClockedEngine::step() {
    pipeline_.step([this] { return issue(); },
                   [this](PairCollector& collector, const Slot& slot) {
                       collector.push(slot.window.row, slot.window.first_column, slot.hits);
                       pushed_hits_ = slot.hits;
                   });
}

}  // namespace cdvp
