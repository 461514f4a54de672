// The sweep of box pruning (sw/baselines/box_pruning.h) at each SIMD width,
// each compiled in its own file for its instruction set.
#pragma once

#include <cstdint>

#include "models/common/aabb.h"

namespace cdvp {

// The sorted boxes a sweep reads, each array padded with at least 8 NaN.
struct PruneArrays {
    const float* key;     // the lower bound on the swept axis, ascending
    const float* min[3];  // the boxes' own bounds
    const float* max[3];
    const uint32_t* index;  // their indices in the frame
    uint32_t count;
    int axis;
};

// Sorted boxes [first, last) against every later box that starts before
// each ends: the overlapping pairs appended to out; stops after a box once
// out holds more than max_pairs.
using PruneSweep = void (*)(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out,
                            uint64_t max_pairs);

void prune_sweep_scalar(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out, uint64_t max_pairs);
#if defined(__x86_64__) || defined(__i386__)
void prune_sweep_sse2(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out, uint64_t max_pairs);
void prune_sweep_avx2(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out, uint64_t max_pairs);
#endif

}  // namespace cdvp
