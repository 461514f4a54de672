// The sweep's schedule: which boxes the address generator puts on its ports
// in which slot. Two shapes behind one interface, chosen from the board's
// TileConfig: the seed's all-pairs sweep over block RAM, and the tiled sweep
// of a board whose boxes live in off-chip SSRAM (docs/tiles.md).
#pragma once

#include "models/address_generator/port_window.h"
#include "models/common/aabb.h"

#include <cstdint>
#include <vector>

#include "models/address_generator/tile_config.h"

namespace cdvp {

// Tile size T, nt = ceil(N/T) tiles; tile a holds boxes [aT, min(N, (a+1)T)).
// Blocks run in the order (0,0), (0,1) .. (0,nt-1), (1,1) .. (nt-1,nt-1):
//   - diagonal (a,a): the seed's triangular sweep of the tile, S(n_a, m) slots;
//   - off-diagonal (a,b), b > a: port 0 on each row i of tile a, the other
//     2m-1 ports walk all of tile b from its first box, n_a x ceil(n_b/(2m-1)) slots.
// Loading a tile from SSRAM takes n x cycles_per_box + latency slots. Block
// k+1's column tile loads while block k is compared (double-buffered), so
//     slots(N) = load(first) + sum_k max(compute_k, load_{k+1})   (none after the last)
// and the slots in which a block waits for its load are bubbles. An untiled
// board is one diagonal block over all N boxes with nothing to load: S(N, m).
// Fewer than two boxes: no sweep, no slots.
class SweepSchedule {
public:
    // One block of the schedule: the row tile, the column tile, its first slot and compute slots.
    struct Block {
        uint32_t row_tile = 0;
        uint32_t column_tile = 0;
        uint64_t start = 0;
        uint64_t compute = 0;
        bool diagonal() const { return row_tile == column_tile; }
    };
    // At most this many tiles (the block list grows with its square).
    static constexpr uint32_t kMaxTiles = 1024;

    SweepSchedule() = default;
    // Throws std::invalid_argument when tiles.boxes gives more than kMaxTiles tiles.
    SweepSchedule(uint32_t m, const TileConfig& tiles, uint32_t objects);

    bool tiled() const { return tiled_; }
    uint32_t objects() const { return objects_; }
    uint32_t lanes() const { return lanes_; }
    uint32_t tile_boxes() const { return tile_boxes_; }
    uint32_t tiles() const { return tile_count_; }
    uint32_t tile_begin(uint32_t tile) const { return tile * tile_boxes_; }
    uint32_t tile_end(uint32_t tile) const;
    const std::vector<Block>& blocks() const { return blocks_; }

    // The end marker's slot: every slot of the sweep, bubbles included.
    uint64_t slots() const { return slots_; }
    // Slots in which the address generator waits for a tile to load (the first load included).
    uint64_t wait_slots() const { return wait_slots_; }
    // Slots to load a tile of n boxes from SSRAM.
    uint64_t load_slots(uint32_t n) const { return uint64_t{n} * cycles_per_box_ + load_latency_; }

    // Block of the pair (i, j), i < j: its index in blocks().
    uint64_t block_of(uint32_t i, uint32_t j) const;
    // Pairs in BoardCore's (i, j) order put in the order this schedule finds
    // them: a stable counting sort by block, O(pairs + blocks). The scratch
    // vectors are the caller's, kept between frames.
    void order_by_block(PairList& pairs, PairList& scratch, std::vector<uint64_t>& block_ends) const;
    // The slot that compares the pair (i, j), i < j < objects.
    uint64_t pair_slot(uint32_t i, uint32_t j) const;

    // S(n, m) = sum_{r=1}^{n-1} ceil(r / lanes): a triangular sweep of n boxes.
    static uint64_t triangle_slots(uint64_t n, uint32_t lanes);

private:
    bool tiled_ = false;
    uint32_t objects_ = 0;
    uint32_t lanes_ = 1;
    uint32_t tile_boxes_ = 0;
    uint32_t tile_count_ = 0;
    uint32_t cycles_per_box_ = 0;
    uint32_t load_latency_ = 0;
    uint64_t slots_ = 0;
    uint64_t wait_slots_ = 0;
    std::vector<Block> blocks_;
};

// The slot sequence the address generator issues, one slot a clock edge that
// moves the pipeline: a window of boxes (port 0 on `row`, ports 1..valid_lanes
// on first_column, first_column+1, ...), a bubble while the next block's
// tiles are not in their buffers, then the end marker. Which blocks are
// ready comes from the caller: the schedule's own block starts (next()), or
// a loader that moves the words (next(ready_blocks), the clocked engine).
class ScheduleWalker {
public:
    struct Slot {
        enum Kind : uint8_t { kWindow, kWait, kEnd } kind = kEnd;
        PortWindow window;   // kWindow only
        uint64_t block = 0;  // the block being compared or waited for
    };

    explicit ScheduleWalker(const SweepSchedule& schedule) : schedule_(&schedule) { restart(); }
    void restart();
    // The slot issued now, then the next: blocks start at the schedule's starts.
    Slot next();
    // The same, but block k may start once k < ready_blocks.
    Slot next(uint64_t ready_blocks);
    // Blocks started so far (a block of no slots starts and ends in one call).
    uint64_t blocks_started() const { return started_; }

private:
    template <class Ready>
    Slot step(Ready ready);
    void enter_block();

    const SweepSchedule* schedule_;
    uint64_t slot_ = 0;
    uint64_t block_ = 0;
    uint64_t started_ = 0;
    uint32_t row_ = 0;
    uint32_t column_ = 0;
    uint32_t row_end_ = 0, column_end_ = 0;  // the block's tiles' ends, kept from enter_block()
    bool in_block_ = false;
};

}  // namespace cdvp
