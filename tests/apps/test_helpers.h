// Helpers for the application tests: a plain broad phase and frame equality.
#pragma once

#include <cstdint>
#include <cstring>

#include "models/common/aabb.h"
#include "sw/scene/scene.h"

namespace cdvp {

// All-pairs AABB overlap on closed intervals, in (first, second) order: the
// candidates the board would report for this frame.
inline PairList overlapping_pairs(const Frame& frame) {
    PairList pairs;
    const auto n = static_cast<uint32_t>(frame.boxes.size());
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t j = i + 1; j < n; ++j) {
            const Box& a = frame.boxes[i];
            const Box& b = frame.boxes[j];
            bool overlap = true;
            for (int axis = 0; axis < 3; ++axis) {
                overlap = overlap && a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis];
            }
            if (overlap) {
                pairs.push_back({i, j});
            }
        }
    }
    return pairs;
}

// Every pair i < j: a broad phase that rejects nothing.
inline PairList all_pairs(std::size_t count) {
    PairList pairs;
    for (uint32_t i = 0; i < count; ++i) {
        for (uint32_t j = i + 1; j < count; ++j) {
            pairs.push_back({i, j});
        }
    }
    return pairs;
}

// Bit-for-bit equality, so "deterministic" means exactly that.
inline bool same_frame(const Frame& a, const Frame& b) {
    return a.number == b.number && a.ids == b.ids && a.boxes.size() == b.boxes.size() &&
           std::memcmp(a.boxes.data(), b.boxes.data(), a.boxes.size() * sizeof(Box)) == 0;
}

}  // namespace cdvp
