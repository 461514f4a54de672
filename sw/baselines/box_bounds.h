// What the pruning baselines (hgrid, prune) need to know of a frame's boxes
// before they place them: which boxes can overlap anything, each box's
// bounds in order, its extents, the axis to sweep.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp {

inline bool has_nan(const FloatBox& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (std::isnan(b.min[axis]) || std::isnan(b.max[axis])) return true;
    }
    return false;
}

// A box with a NaN bound overlaps nothing (every comparison with NaN is
// false): the others, by index.
inline void valid_boxes(const std::vector<FloatBox>& boxes, std::vector<uint32_t>& valid) {
    valid.clear();
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        if (!has_nan(boxes[i])) valid.push_back(i);
    }
}

// The axis along which the boxes' centres spread most: sweeping it leaves
// the fewest boxes overlapping any one's interval (a scene flat in x would
// otherwise test nearly every pair). Unbounded boxes have no centre to count.
inline int widest_axis(const std::vector<FloatBox>& boxes, const std::vector<uint32_t>& index) {
    double sum[3] = {}, squares[3] = {}, count[3] = {};
    for (const uint32_t i : index) {
        for (int axis = 0; axis < 3; ++axis) {
            const double centre = 0.5 * (double(boxes[i].min[axis]) + double(boxes[i].max[axis]));
            if (!std::isfinite(centre)) continue;
            sum[axis] += centre;
            squares[axis] += centre * centre;
            count[axis] += 1;
        }
    }
    int widest = 0;
    double spread = -1;
    for (int axis = 0; axis < 3; ++axis) {
        const double n = std::max(count[axis], 1.0);
        const double variance = squares[axis] / n - (sum[axis] / n) * (sum[axis] / n);
        if (variance > spread) spread = variance, widest = axis;
    }
    return widest;
}

// The box between a box's bounds, whichever is larger: an inverted box (min
// above max on an axis) overlaps only boxes that contain the interval
// between its bounds, so what overlaps it overlaps this box too. Placing the
// boxes by these bounds and testing candidates exactly keeps every pair.
inline void normalised(const FloatBox& b, float lo[3], float hi[3]) {
    for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = std::min(b.min[axis], b.max[axis]);
        hi[axis] = std::max(b.min[axis], b.max[axis]);
    }
}

// The normalised box's extent on an axis (infinite for an unbounded box; a
// point at infinity has none).
inline float extent(const FloatBox& b, int axis) {
    const float e = std::fabs(b.max[axis] - b.min[axis]);
    return std::isnan(e) ? 0.0f : e;
}

}  // namespace cdvp
