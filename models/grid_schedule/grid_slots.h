// The grid board's slots in closed form (docs/grid_board.md, "The cycle
// formula"): what each pass, cell and large tile costs, where each block
// starts, and a sweep's worst case. The fast engine places every pair with
// these; the clocked engine finds the same slots by walking the passes, and
// the tests hold the two together.
#pragma once

#include <algorithm>
#include <cstdint>

#include "models/address_generator/sweep_schedule.h"
#include "models/grid_binning/grid_config.h"

namespace cdvp {

// What a grid sweep showed: the grid registers after it (docs/grid_board.md, "Registers").
struct GridSweepStats {
    uint32_t dims = 0;           // cells a side
    uint32_t large_boxes = 0;    // inverted, spanning or overflowing: swept against every box
    uint32_t overflow_boxes = 0; // of those, met a full cell or a full entry memory
    uint32_t excluded_boxes = 0; // a NaN bound (float32)
    uint64_t cell_entries = 0;
    uint32_t busy_cells = 0;     // cells of two boxes or more
    uint64_t slots = 0;          // the sweep's slots, the end marker's
    friend bool operator==(const GridSweepStats& a, const GridSweepStats& b) {
        return a.dims == b.dims && a.large_boxes == b.large_boxes && a.overflow_boxes == b.overflow_boxes &&
               a.excluded_boxes == b.excluded_boxes && a.cell_entries == b.cell_entries &&
               a.busy_cells == b.busy_cells && a.slots == b.slots;
    }
};

// The cost of each piece: w lanes, q slots a box read from the box store,
// l the SSRAM's read latency.
struct GridSlots {
    uint32_t lanes = 1;
    uint32_t cycles_per_box = 1;  // q
    uint32_t latency = 2;         // l

    // Pass 1: every box read once.
    uint64_t bounds(uint64_t objects) const { return objects * cycles_per_box + latency; }
    static constexpr uint64_t setup() { return GridConfig::kSetupSlots; }
    // One box of a pass that touches k cells (0: none): q, or k when more.
    uint64_t box(uint64_t cells) const { return std::max<uint64_t>(cycles_per_box, cells); }
    // Passes 2 and 3: the sum of box() over the boxes, and the pipeline's fill.
    uint64_t pass(uint64_t box_slots) const { return box_slots + latency + GridConfig::kCellFunctionSlots; }
    // Loading n boxes into the cell buffer: entries, then boxes by index, then the cell function.
    uint64_t load(uint64_t n) const { return n * cycles_per_box + 2ull * latency + GridConfig::kCellFunctionSlots; }
    // The seed's triangle over a cell of n boxes: S(n, m).
    uint64_t triangle(uint64_t n) const { return SweepSchedule::triangle_slots(n, lanes); }
    // One box streamed past a large tile, compared with `columns` of its boxes.
    uint64_t stream_box(uint64_t columns) const {
        return std::max<uint64_t>(cycles_per_box, (columns + lanes - 1) / lanes);
    }
    // Before a tile's stream: its load and the first box's read.
    uint64_t tile_lead(uint64_t n) const { return load(n) + latency; }
};

// The cell sweep's blocks: load(first) + sum_k max(S(n_k), load_{k+1}); a
// cell's load overlaps the sweep of the cell before it (double-buffered).
class CellBlocks {
public:
    CellBlocks(const GridSlots& slots, uint64_t begin) : slots_(slots), end_(begin) {}
    // The next busy cell of n boxes: the slot of its first compare.
    uint64_t add(uint64_t n) {
        const uint64_t load = slots_.load(n);
        start_ = any_ ? start_ + std::max(compute_, load) : end_ + load;
        compute_ = slots_.triangle(n);
        any_ = true;
        return start_;
    }
    // The slot after the last cell's last compare (the begin when none).
    uint64_t end() const { return any_ ? start_ + compute_ : end_; }

private:
    GridSlots slots_;
    uint64_t end_;
    uint64_t start_ = 0, compute_ = 0;
    bool any_ = false;
};

// At most how many slots a grid sweep of `objects` boxes takes, whatever
// the boxes (the driver's timeouts): every box spanning max_span cells in
// both passes, the entries in full cells, and every box large.
uint64_t worst_grid_slots(uint64_t objects, const GridConfig& grid, const GridSlots& slots);

}  // namespace cdvp
