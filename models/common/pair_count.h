// How many pairs of boxes overlap, counted cheaply: sort on one axis, sweep,
// test the other two. The board's semantics exactly: float32 bounds, closed
// intervals (touching boxes overlap), and IEEE comparisons, so a box with a
// NaN bound overlaps nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp {

// Small scenes: sort and sweep, O(N + candidates), candidates being the
// pairs that overlap on the swept axis (the axis whose box centres spread
// widest against the boxes' mean extent; a radix sort on the bounds' bits).
// Larger ones: a uniform grid of cells about the boxes' mean size, each box
// in the cells its extent covers, each pair tested in the cells it shares and
// counted in one of them only (O(N + pairs) on scenes of boxes of like size);
// a box covering many cells is tested against every box instead.
class PairCounter {
public:
    uint64_t count(const std::vector<FloatBox>& boxes);
    // Below this many boxes the sweep is cheaper than filling a grid.
    static constexpr std::size_t kGridFrom = 256;
    uint64_t count_by_sweep(const std::vector<FloatBox>& boxes);
    uint64_t count_by_grid(const std::vector<FloatBox>& boxes);

private:
    // Kept between calls, so that counting frame after frame allocates nothing.
    std::vector<uint32_t> order_, scratch_;
    std::vector<uint32_t> keys_, scratch_keys_;
    std::vector<float> bounds_;  // the sorted boxes, six floats each
    struct CellRange {
        uint32_t low[3], high[3];
    };
    std::vector<CellRange> ranges_;
    std::vector<uint32_t> cell_start_, cell_boxes_, valid_, big_;
};

// The same count by comparing every pair: the reference for tests.
uint64_t count_pairs_brute_force(const std::vector<FloatBox>& boxes);

}  // namespace cdvp
