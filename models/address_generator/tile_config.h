// Where a board keeps its boxes during a sweep.
#pragma once

#include <cstdint>

namespace cdvp {

// boxes = 0: every box sits in the coordinate memories (block RAM), the
// seed's board. boxes = T > 0: the boxes sit in off-chip SSRAM, one bank
// per coordinate memory, and the board sweeps them in tiles of T boxes
// through double-buffered block-RAM tile buffers (docs/tiles.md).
struct TileConfig {
    uint32_t boxes = 0;
    // SSRAM read pipeline: address to data (pipelined ZBT: 2).
    uint32_t load_latency_cycles = 2;
    // Cycles to read one box's six coordinates: ceil(6 / banks), 1 with six banks.
    uint32_t cycles_per_box = 1;

    bool tiled() const { return boxes != 0; }
    // The runs a row's pairs may come in over a sweep of `objects` boxes:
    // one in block RAM, one a column tile when tiled.
    uint64_t row_pieces(uint32_t objects) const { return tiled() ? (uint64_t{objects} + boxes - 1) / boxes : 1; }
    friend bool operator==(const TileConfig& a, const TileConfig& b) {
        return a.boxes == b.boxes && a.load_latency_cycles == b.load_latency_cycles &&
               a.cycles_per_box == b.cycles_per_box;
    }
};

}  // namespace cdvp
