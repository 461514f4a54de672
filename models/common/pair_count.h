// How many pairs of boxes overlap, counted cheaply: sort on one axis, sweep,
// test the other two. The board's semantics exactly: float32 bounds, closed
// intervals (touching boxes overlap), and IEEE comparisons, so a box with a
// NaN bound overlaps nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp {

// Sort-and-sweep: O(N + candidates), candidates being the pairs that overlap
// on the swept axis (the axis whose box centres spread widest against the
// boxes' mean extent). The sort is a radix sort on the bounds' bit patterns.
class PairCounter {
public:
    uint64_t count(const std::vector<FloatBox>& boxes);

private:
    // Kept between calls, so that counting frame after frame allocates nothing.
    std::vector<uint32_t> order_, scratch_;
    std::vector<uint32_t> keys_, scratch_keys_;
    std::vector<float> bounds_;  // the sorted boxes, six floats each
};

// The same count by comparing every pair: the reference for tests.
uint64_t count_pairs_brute_force(const std::vector<FloatBox>& boxes);

}  // namespace cdvp
