// Boxes as structure-of-arrays and the comparison unit's test on a block of them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "models/comparison_unit/comparison_unit.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cdvp {

// Bounds by coordinate (Coordinate order), one float per box. The arrays
// carry kBlock entries of padding so that a block may start at any box.
struct BoxColumns {
    static constexpr std::size_t kBlock = 8;

    std::vector<float> bound[kCoordinates];

    void resize(std::size_t boxes) {
        for (auto& column : bound) column.resize(boxes + kBlock, std::numeric_limits<float>::quiet_NaN());
    }
    void set(std::size_t k, const float (&bounds)[kCoordinates]) {
        for (uint32_t c = 0; c < kCoordinates; ++c) bound[c][k] = bounds[c];
    }
    void get(std::size_t k, float (&bounds)[kCoordinates]) const {
        for (uint32_t c = 0; c < kCoordinates; ++c) bounds[c] = bound[c][k];
    }
};

// Bit k set = ComparisonUnit::lane_hit(a, box q0 + k) for the kBlock boxes
// from q0. Every comparison is evaluated (no branch), as IEEE float
// comparisons: NaN never compares true, -0 equals +0, infinities are ordinary.
inline uint32_t block_hits(const BoxColumns& boxes, std::size_t q0, const float (&a)[kCoordinates]) {
    const float* const b[kCoordinates] = {boxes.bound[kMinX].data() + q0, boxes.bound[kMinY].data() + q0,
                                          boxes.bound[kMinZ].data() + q0, boxes.bound[kMaxX].data() + q0,
                                          boxes.bound[kMaxY].data() + q0, boxes.bound[kMaxZ].data() + q0};
#if defined(__SSE2__)
    uint32_t hits = 0;
    for (std::size_t half = 0; half < BoxColumns::kBlock; half += 4) {
        __m128 all = _mm_castsi128_ps(_mm_set1_epi32(-1));
        for (uint32_t axis = 0; axis < 3; ++axis) {
            const __m128 b_min = _mm_loadu_ps(b[axis] + half), b_max = _mm_loadu_ps(b[axis + 3] + half);
            // a.min <= b.max and b.min <= a.max
            all = _mm_and_ps(all, _mm_cmple_ps(_mm_set1_ps(a[axis]), b_max));
            all = _mm_and_ps(all, _mm_cmple_ps(b_min, _mm_set1_ps(a[axis + 3])));
        }
        hits |= static_cast<uint32_t>(_mm_movemask_ps(all)) << half;
    }
    return hits;
#else
    uint32_t hits = 0;
    for (std::size_t k = 0; k < BoxColumns::kBlock; ++k) {
        const float other[kCoordinates] = {b[0][k], b[1][k], b[2][k], b[3][k], b[4][k], b[5][k]};
        hits |= static_cast<uint32_t>(ComparisonUnit::lane_hit(a, other)) << k;
    }
    return hits;
#endif
}

// The bits of a block from q0 that lie before `end`.
inline uint32_t block_mask_before(std::size_t q0, std::size_t end) {
    const std::size_t inside = end - q0;
    return inside >= BoxColumns::kBlock ? (1u << BoxColumns::kBlock) - 1 : (1u << inside) - 1;
}

}  // namespace cdvp
