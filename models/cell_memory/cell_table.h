// The grid board's cell memory (docs/grid_board.md, "Memory"): the count
// table, the cell entry lists and the busy-cell list, as the binning passes
// write them and the cell loader reads them. On the board they sit in SSRAM;
// here they are arrays of words with the passes' operations on them.
#pragma once

#include <cstdint>
#include <vector>

#include "models/grid_binning/grid_geometry.h"

namespace cdvp {

// A cell of two boxes or more, as the scan lists it: its number, its first
// entry in the entry lists and its boxes.
struct BusyCell {
    uint32_t cell = 0;
    uint32_t first = 0;
    uint32_t count = 0;
};

class CellTable {
public:
    // A new sweep over `cells` cells: every count 0, no entries. A cell
    // holds at most `capacity` boxes, the entry lists `entry_capacity`.
    void reset(uint64_t cells, uint32_t capacity, uint64_t entry_capacity);

    // Pass 2 (count), one box: when each cell of `range` holds fewer than
    // `capacity` boxes and the entry lists have room for them all, counts the
    // box in each and returns true; else changes nothing (the box overflows).
    bool count(const CellRange& range, const GridGeometry& grid) {
        const uint64_t k = range.cells();
        if (k > entry_capacity_ - entries_) return false;
        bool room = true;
        for_each_cell(range, grid, [&](uint64_t c) { room &= counts_[c] < capacity_; });
        if (!room) return false;
        for_each_cell(range, grid, [&](uint64_t c) { ++counts_[c]; });
        entries_ += k;
        return true;
    }
    uint64_t entries() const { return entries_; }

    // The scan, a cell at a time in ascending order: each count becomes the
    // cell's first entry, and a cell of two boxes or more joins the busy list.
    void begin_scan();
    void scan_cell(uint64_t cell) {
        const uint32_t n = counts_[cell];
        counts_[cell] = scanned_;
        if (n >= 2) busy_.push_back({static_cast<uint32_t>(cell), scanned_, n});
        scanned_ += n;
    }
    void scan() {
        begin_scan();
        for (uint64_t c = 0; c < cells_; ++c) scan_cell(c);
    }

    // Pass 3 (place), one box counted in pass 2: its index at the next entry
    // of each cell of its range. Boxes placed in index order keep every list
    // in index order.
    void place(uint32_t box, const CellRange& range, const GridGeometry& grid) {
        for_each_cell(range, grid, [&](uint64_t c) { entries_list_[counts_[c]++] = box; });
    }

    uint64_t cells() const { return cells_; }
    const std::vector<BusyCell>& busy_cells() const { return busy_; }
    // The boxes of a busy cell, in index order.
    const uint32_t* list(const BusyCell& cell) const { return entries_list_.data() + cell.first; }
    // A cell's count (before the scan) or next entry (after it), for tests.
    uint32_t word(uint64_t cell) const { return counts_[cell]; }

    // Every cell of a range, x fastest.
    template <class Visit>
    static void for_each_cell(const CellRange& range, const GridGeometry& grid, Visit&& visit) {
        for (uint32_t z = range.lo[2]; z <= range.hi[2]; ++z) {
            for (uint32_t y = range.lo[1]; y <= range.hi[1]; ++y) {
                const uint64_t row = grid.linear(0, y, z);
                for (uint32_t x = range.lo[0]; x <= range.hi[0]; ++x) visit(row + x);
            }
        }
    }

private:
    uint64_t cells_ = 0;
    uint32_t capacity_ = 0;
    uint64_t entry_capacity_ = 0;
    uint64_t entries_ = 0;
    uint32_t scanned_ = 0;
    std::vector<uint32_t> counts_;
    std::vector<uint32_t> entries_list_;
    std::vector<BusyCell> busy_;
};

}  // namespace cdvp
