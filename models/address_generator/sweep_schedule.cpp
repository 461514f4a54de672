#include "models/address_generator/sweep_schedule.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/common/integer_math.h"

namespace cdvp {

uint64_t SweepSchedule::triangle_slots(uint64_t n, uint32_t lanes) {
    // Closed form of sum_{r=1}^{n-1} ceil(r / w): full groups of w rows
    // contribute w*q each for q = 1..Q, and the last partial group R rows of Q+1.
    if (n < 2) return 0;
    const uint64_t w = lanes;
    const uint64_t q = (n - 1) / w;
    const uint64_t r = (n - 1) % w;
    return w * q * (q + 1) / 2 + r * (q + 1);
}

SweepSchedule::SweepSchedule(uint32_t m, const TileConfig& tiles, uint32_t objects)
    : tiled_(tiles.tiled()), objects_(objects), lanes_(2 * m - 1) {
    if (m == 0) throw std::invalid_argument("the sweep schedule needs m >= 1");
    if (!tiled_) {
        tile_boxes_ = objects;
        tile_count_ = objects > 0 ? 1 : 0;
        if (objects >= 2) blocks_.push_back({0, 0, 0, triangle_slots(objects, lanes_)});
        slots_ = blocks_.empty() ? 0 : blocks_.front().compute;
        return;
    }
    tile_boxes_ = tiles.boxes;
    cycles_per_box_ = tiles.cycles_per_box;
    load_latency_ = tiles.load_latency_cycles;
    const uint64_t count = ceil_div(objects, tile_boxes_);
    if (count > kMaxTiles) {
        throw std::invalid_argument("tile_boxes: expected at most " + std::to_string(kMaxTiles) + " tiles of " +
                                    std::to_string(tile_boxes_) + " boxes for " + std::to_string(objects) +
                                    " boxes, got " + std::to_string(count));
    }
    tile_count_ = static_cast<uint32_t>(count);
    if (objects < 2) return;  // nothing to compare: nothing is loaded
    blocks_.reserve(uint64_t{tile_count_} * (tile_count_ + 1) / 2);
    for (uint32_t a = 0; a < tile_count_; ++a) {
        const uint32_t rows = tile_end(a) - tile_begin(a);
        for (uint32_t b = a; b < tile_count_; ++b) {
            const uint32_t columns = tile_end(b) - tile_begin(b);
            const uint64_t compute =
                a == b ? triangle_slots(rows, lanes_) : uint64_t{rows} * ceil_div(columns, lanes_);
            blocks_.push_back({a, b, 0, compute});
        }
    }
    // Block k+1's column tile loads while block k computes; the first load
    // (row and column tile 0) comes before anything else.
    uint64_t slot = load_slots(tile_end(0));
    wait_slots_ = slot;
    for (std::size_t k = 0; k < blocks_.size(); ++k) {
        blocks_[k].start = slot;
        const uint64_t next_load =
            k + 1 < blocks_.size()
                ? load_slots(tile_end(blocks_[k + 1].column_tile) - tile_begin(blocks_[k + 1].column_tile))
                : 0;
        const uint64_t span = std::max(blocks_[k].compute, next_load);
        wait_slots_ += span - blocks_[k].compute;
        slot += span;
    }
    slots_ = slot;
}

uint32_t SweepSchedule::tile_end(uint32_t tile) const {
    return static_cast<uint32_t>(std::min<uint64_t>(objects_, (uint64_t{tile} + 1) * tile_boxes_));
}

uint64_t SweepSchedule::block_of(uint32_t i, uint32_t j) const {
    if (!tiled_) return 0;
    const uint64_t a = i / tile_boxes_, b = j / tile_boxes_;
    return a * tile_count_ - a * (a - 1) / 2 + (b - a);
}

uint64_t SweepSchedule::pair_slot(uint32_t i, uint32_t j) const {
    const Block& block = blocks_[block_of(i, j)];
    const uint32_t first_row = tile_begin(block.row_tile);
    if (block.diagonal()) {
        const uint64_t n = tile_end(block.row_tile) - first_row;
        return block.start + block.compute - triangle_slots(n - (i - first_row), lanes_) + (j - i - 1) / lanes_;
    }
    const uint32_t first_column = tile_begin(block.column_tile);
    const uint64_t per_row = ceil_div(tile_end(block.column_tile) - first_column, lanes_);
    return block.start + (i - first_row) * per_row + (j - first_column) / lanes_;
}

void ScheduleWalker::restart() {
    slot_ = 0;
    block_ = 0;
    started_ = 0;
    in_block_ = false;
}

void ScheduleWalker::enter_block() {
    const SweepSchedule::Block& block = schedule_->blocks()[block_];
    row_ = schedule_->tile_begin(block.row_tile);
    column_ = block.diagonal() ? row_ + 1 : schedule_->tile_begin(block.column_tile);
    row_end_ = schedule_->tile_end(block.row_tile);
    column_end_ = schedule_->tile_end(block.column_tile);
    in_block_ = true;
    ++started_;
}

template <class Ready>
ScheduleWalker::Slot ScheduleWalker::step(Ready ready) {
    const std::vector<SweepSchedule::Block>& blocks = schedule_->blocks();
    const uint32_t lanes = schedule_->lanes();
    while (block_ < blocks.size()) {
        const SweepSchedule::Block& block = blocks[block_];
        if (!in_block_) {
            if (!ready(block, block_)) {
                ++slot_;
                Slot wait;
                wait.kind = Slot::kWait;
                wait.block = block_;
                return wait;
            }
            enter_block();
        }
        const uint32_t row_end = row_end_, column_end = column_end_;
        if (row_ >= row_end || column_ >= column_end) {  // the block is done
            ++block_;
            in_block_ = false;
            continue;
        }
        Slot window{Slot::kWindow, {row_, column_, std::min(lanes, column_end - column_)}, block_};
        column_ += lanes;
        if (column_ >= column_end) {
            ++row_;
            column_ = block.diagonal() ? row_ + 1 : schedule_->tile_begin(block.column_tile);
        }
        ++slot_;
        return window;
    }
    return Slot{};
}

ScheduleWalker::Slot ScheduleWalker::next() {
    return step([this](const SweepSchedule::Block& block, uint64_t) { return slot_ >= block.start; });
}

ScheduleWalker::Slot ScheduleWalker::next(uint64_t ready_blocks) {
    return step([ready_blocks](const SweepSchedule::Block&, uint64_t k) { return k < ready_blocks; });
}

void SweepSchedule::order_by_block(PairList& pairs, PairList& scratch, std::vector<uint64_t>& block_ends) const {
    block_ends.assign(blocks().size() + 1, 0);
    for (const IndexPair& p : pairs) ++block_ends[block_of(p.first, p.second) + 1];
    for (std::size_t k = 1; k < block_ends.size(); ++k) block_ends[k] += block_ends[k - 1];
    scratch.resize(pairs.size());
    for (const IndexPair& p : pairs) scratch[block_ends[block_of(p.first, p.second)]++] = p;
    pairs.swap(scratch);
}

}  // namespace cdvp
