// Software all-pairs tests with the board's semantics: float32, closed intervals.
#pragma once

#include <cstddef>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp {

// The reference: every pair i < j whose boxes overlap on all three axes
// (min_a <= max_b and min_b <= max_a), sorted by (i, j). Written without any
// of the board's code so that tests compare two independent implementations.
PairList reference_pairs(const std::vector<FloatBox>& boxes);

// The same loop as a plain scalar baseline: the speed yardstick for the
// cycle-level model. Appends to out (cleared first) and returns its size.
size_t brute_force_pairs(const std::vector<FloatBox>& boxes, PairList& out);

}  // namespace cdvp
