// The grid board's cell buffer (docs/grid_board.md, "The cell sweep"): two
// halves of 2m-port block RAM, each holding the boxes of one cell (or one
// large tile) with their indices and first cells, and the loader that fills
// the idle half from the box store while the lanes read the other. A load
// of n boxes takes GridSlots::load(n) slots: two SSRAM latencies and the
// cell function fill the pipeline, then a box lands every q slots.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "models/comparison_unit/comparison_unit.h"
#include "models/grid_binning/grid_geometry.h"
#include "models/grid_schedule/grid_slots.h"

namespace cdvp {

class CellBuffer {
public:
    struct Half {
        CoordinateMemories boxes;              // six coordinates, 2m ports
        std::array<std::vector<uint8_t>, 3> first;  // each box's first cell per axis
        std::vector<uint32_t> index;           // each box's index in the frame
        uint32_t count = 0;
    };

    CellBuffer(uint32_t m, uint32_t capacity, const GridSlots& slots, NumberFormat format);

    // Begins loading `count` boxes (their indices at `boxes`, which must
    // stay valid) into half `half`; only while no load is under way.
    void begin(uint32_t half, const uint32_t* boxes, uint32_t count);
    // The box store: per coordinate, each box's stored word (the board's
    // CoordinateStore).
    using Store = std::array<std::vector<uint32_t>, kCoordinates>;
    // One slot of the load under way (none: nothing): the box due in this
    // slot lands, its words from `store`, its first cells from `grid`.
    // Returns true when the load's last slot was this one.
    bool tick(const Store& store, const GridGeometry& grid);
    bool loading() const { return loading_; }

    Half& half(uint32_t k) { return halves_[k]; }
    const Half& half(uint32_t k) const { return halves_[k]; }
    // Block RAM primitives of both halves (BoardConfig::block_rams).
    uint32_t block_rams() const { return 2 * block_rams_of(halves_[0].boxes, layout_); }

private:
    GridSlots slots_;
    NumberFormat format_;
    BlockRamLayout layout_;
    std::array<Half, 2> halves_;
    bool loading_ = false;
    uint32_t half_ = 0;
    const uint32_t* boxes_ = nullptr;
    uint32_t count_ = 0;
    uint64_t slot_ = 0;  // slots of the load so far
};

}  // namespace cdvp
