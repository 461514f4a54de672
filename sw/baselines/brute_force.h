// Software all-pairs tests with the board's semantics: float32, closed intervals.
#pragma once

#include <cstddef>
#include <vector>

#include "models/common/aabb.h"
#include "models/common/pair_budget.h"

namespace cdvp {

// The exact test: a and b overlap on all three axes (min_a <= max_b and
// min_b <= max_a; touching boxes overlap). Inexact baselines filter by it.
inline bool boxes_overlap(const FloatBox& a, const FloatBox& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis])) return false;
    }
    return true;
}

// The reference: every pair i < j whose boxes overlap on all three axes
// (min_a <= max_b and min_b <= max_a), sorted by (i, j). Written without any
// of the board's code so that tests compare two independent implementations.
PairList reference_pairs(const std::vector<FloatBox>& boxes);

// The same loop as a plain scalar baseline: the speed yardstick for the
// cycle-level model. Appends to out (cleared first) and returns its size;
// throws PairBudgetExceeded rather than outgrow the budget.
size_t brute_force_pairs(const std::vector<FloatBox>& boxes, PairList& out, const PairBudget& budget = {});

}  // namespace cdvp
