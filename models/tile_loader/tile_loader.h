// The tiled board's loader: SSRAM banks into the block-RAM tile buffers.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "models/address_generator/sweep_schedule.h"
#include "models/board_spec/board_config.h"
#include "models/board_spec/board_engine.h"

namespace cdvp {

// Owns the boxes as the host wrote them into SSRAM (one bank per coordinate)
// and the tile buffers: column memories (2m ports, m copies) and row memories
// (port 0), each ping/pong. A load reads one box every cycles_per_box slots
// (one coordinate group a slot), each word landing in its buffer
// load_latency_cycles slots after its read; a tile is readable from the slot
// after its last word lands, so loading n boxes takes n x cycles_per_box +
// latency slots, as the schedule assumes. It is clocked in address-generator
// slots: a stalled pipeline holds it too.
class TileLoader {
public:
    TileLoader(const BoardConfig& config, uint32_t capacity);

    // A new sweep: the SSRAM holds `store`'s first objects boxes; nothing is loaded.
    void start(const CoordinateStore& store, uint32_t objects, const SweepSchedule& schedule);
    // Begins loading the tiles of `block` (only once the previous load has landed):
    // its column tile into column buffer block % 2, and for block 0 and blocks
    // (a, a+1) the same words into the row buffer of their column tile.
    void begin(uint64_t block);
    // One slot: land() first (the words due now reach their buffers), read()
    // last (this slot's SSRAM reads; the slot ends).
    void land();
    void read();

    // Blocks whose tiles are all in their buffers and readable in this slot.
    uint64_t ready_blocks() const { return ready_; }
    bool busy() const { return reading_ || !in_flight_.empty(); }
    CoordinateMemories& columns(uint64_t block) { return columns_[block % 2]; }
    CoordinateMemories& rows(uint32_t row_tile) { return rows_[row_tile % 2]; }
    uint32_t block_rams() const;

private:
    // A word group read in one slot: coordinates [first, last) of one box.
    struct Read {
        uint64_t due;
        uint32_t box;
        uint32_t first, last;
    };
    void apply_due();

    TileConfig tiles_;
    BlockRamLayout layout_;  // the tile buffers' primitives
    std::vector<CoordinateMemories> columns_, rows_;
    CoordinateStore ssram_;
    const SweepSchedule* schedule_ = nullptr;
    uint64_t slot_ = 0;
    // The load under way: its block, tiles, and how many reads are issued.
    uint64_t block_ = 0;
    bool reading_ = false;
    bool with_row_ = false;
    uint32_t tile_first_ = 0, tile_boxes_ = 0;
    uint64_t reads_issued_ = 0;
    std::deque<Read> in_flight_;
    uint64_t ready_ = 0;
    bool landed_ = false;  // the load's last word landed: ready at the next slot
};

}  // namespace cdvp
