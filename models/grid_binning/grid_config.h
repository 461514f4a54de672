// What a grid board is built with (docs/grid_board.md): its grid, its cell
// lists' capacity and the span a binned box may have. Beside the binning
// stage, as TileConfig sits beside the address generator, because
// BoardConfig (above) holds it.
#pragma once

#include <cstdint>

namespace cdvp {

struct GridConfig {
    // Cells a side (dims^3 in all); 0: chosen at START from the boxes, the
    // largest g with kBoxesPerCell g^3 <= N.
    uint32_t dims = 0;
    // Cubic cells of this size in the board's coordinate units (scene units
    // in float32, codes in fixedK), from the frame's least bounds; 0: the
    // grid fitted to the frame's bounds.
    float cell_size = 0.0f;
    // Boxes a cell list, and so the cell buffer, holds: one 512 x 36 block
    // RAM deep by default, the seed's board's own limit.
    uint32_t cell_capacity = 512;
    // Cells a binned box may cover; a box covering more is swept against
    // every box instead (2 x 2 x 2 by default).
    uint32_t max_span = 8;
    // Cell entries the board's memory holds (platform/memory_plan.h); a box
    // whose entries would not fit is swept against every box (overflow).
    uint64_t entry_capacity = kUnboundedEntries;

    static constexpr uint64_t kUnboundedEntries = UINT64_MAX;
    // The automatic grid's boxes a cell (by first cell): 16, because a cell's
    // load costs two SSRAM latencies and the cell function beside its boxes,
    // so smaller cells spend the sweep on latencies and larger ones on the
    // lanes' triangles (docs/grid_board.md, "Choosing the grid").
    static constexpr uint64_t kBoxesPerCell = 16;
    static constexpr uint32_t kMaxDims = 256;  // a cell coordinate fits a byte
    static constexpr uint32_t kMinCellCapacity = 2;
    static constexpr uint32_t kMaxCellCapacity = 65536;
    static constexpr uint32_t kMaxSpan = 64;
    // Slots to derive the origin and scale from the bounds: one pipelined
    // float divider for three axes (assumption).
    static constexpr uint32_t kSetupSlots = 16;
    // The cell function's pipeline: a float subtract and a multiply of two
    // stages each (assumption).
    static constexpr uint32_t kCellFunctionSlots = 4;

    // The cells a side of a sweep of `objects` boxes.
    uint32_t dims_for(uint64_t objects) const;
    uint64_t cells_for(uint64_t objects) const {
        const uint64_t d = dims_for(objects);
        return d * d * d;
    }
    // Throws std::invalid_argument with one line naming the setting.
    void validate() const;
    friend bool operator==(const GridConfig& a, const GridConfig& b) {
        return a.dims == b.dims && a.cell_size == b.cell_size && a.cell_capacity == b.cell_capacity &&
               a.max_span == b.max_span && a.entry_capacity == b.entry_capacity;
    }
};

}  // namespace cdvp
