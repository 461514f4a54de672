#include "models/tile_loader/tile_loader.h"

#include <algorithm>
#include <stdexcept>

namespace cdvp {

TileLoader::TileLoader(const BoardConfig& config, uint32_t capacity) : tiles_(config.tiles) {
    const uint32_t depth = std::max(1u, std::min(config.tiles.boxes, capacity));
    layout_ = config.format.block_ram_layout(depth);
    for (int buffer = 0; buffer < 2; ++buffer) {
        columns_.push_back(make_coordinate_memories(config.m, depth, layout_));
        rows_.push_back(make_coordinate_memories(1, depth, layout_));
    }
}

uint32_t TileLoader::block_rams() const {
    uint32_t total = 0;
    for (const auto* set : {&columns_, &rows_}) {
        for (const CoordinateMemories& memories : *set) total += block_rams_of(memories, layout_);
    }
    return total;
}

void TileLoader::start(const CoordinateStore& store, uint32_t objects, const SweepSchedule& schedule) {
    for (uint32_t c = 0; c < kCoordinates; ++c) ssram_[c].assign(store[c].begin(), store[c].begin() + objects);
    schedule_ = &schedule;
    slot_ = 0;
    reading_ = landed_ = false;
    in_flight_.clear();
    ready_ = 0;
}

void TileLoader::begin(uint64_t block) {
    if (busy() || block != ready_) throw std::logic_error("tile loader: a load begun before the last one landed");
    const SweepSchedule::Block& b = schedule_->blocks()[block];
    block_ = block;
    tile_first_ = schedule_->tile_begin(b.column_tile);
    tile_boxes_ = schedule_->tile_end(b.column_tile) - tile_first_;
    with_row_ = block == 0 || b.column_tile == b.row_tile + 1;
    reads_issued_ = 0;
    reading_ = true;
}

void TileLoader::land() {
    if (landed_) {  // the last word landed in an earlier slot: readable now
        ready_ = block_ + 1;
        landed_ = false;
    }
    apply_due();
}

void TileLoader::read() {
    if (reading_) {
        // One coordinate group a slot: the banks read in turns when fewer than six.
        const uint32_t per_box = tiles_.cycles_per_box;
        const uint32_t box = tile_first_ + static_cast<uint32_t>(reads_issued_ / per_box);
        const auto group = static_cast<uint32_t>(reads_issued_ % per_box);
        const uint32_t first = group * kCoordinates / per_box, last = (group + 1) * kCoordinates / per_box;
        in_flight_.push_back({slot_ + tiles_.load_latency_cycles, box, first, last});
        reading_ = ++reads_issued_ < uint64_t{tile_boxes_} * per_box;
    }
    apply_due();  // a latency of 0 lands in the slot of its read
    ++slot_;
}

void TileLoader::apply_due() {
    while (!in_flight_.empty() && in_flight_.front().due <= slot_) {
        const Read r = in_flight_.front();
        in_flight_.pop_front();
        const uint32_t at = r.box - tile_first_;
        for (uint32_t c = r.first; c < r.last; ++c) {
            columns(block_)[c].write(at, ssram_[c][r.box]);
            if (with_row_) rows(schedule_->blocks()[block_].column_tile)[c].write(at, ssram_[c][r.box]);
        }
        if (!reading_ && in_flight_.empty()) landed_ = true;  // the tile's last word: readable from the next slot
    }
}

}  // namespace cdvp
