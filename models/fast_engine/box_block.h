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
    static constexpr std::size_t kBlock = 4;  // a multiple of 4: BlockTest tests groups of four

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

// The comparison unit's test of box a against kBlock boxes at a time: bit k
// of hits(q0) = ComparisonUnit::lane_hit(a, box q0 + k). Every comparison is
// evaluated (no branch), as IEEE float comparisons: NaN never compares true,
// -0 equals +0, infinities are ordinary.
class BlockTest {
public:
    BlockTest(const BoxColumns& boxes, const float (&a)[kCoordinates]) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            column_[c] = boxes.bound[c].data();
#if defined(__SSE2__)
            a_[c] = _mm_set1_ps(a[c]);
#else
            a_[c] = a[c];
#endif
        }
    }

    uint32_t hits(std::size_t q0) const {
#if defined(__SSE2__)
        uint32_t hits = 0;
        for (std::size_t group = 0; group < BoxColumns::kBlock; group += 4) hits |= four(q0 + group) << group;
        return hits;
#else
        uint32_t hits = 0;
        for (std::size_t k = 0; k < BoxColumns::kBlock; ++k) {
            float b[kCoordinates];
            for (uint32_t c = 0; c < kCoordinates; ++c) b[c] = column_[c][q0 + k];
            hits |= static_cast<uint32_t>(ComparisonUnit::lane_hit(a_, b)) << k;
        }
        return hits;
#endif
    }

private:
#if defined(__SSE2__)
    uint32_t four(std::size_t q) const {
        // a.min <= b.max and b.min <= a.max on each axis.
        __m128 all = _mm_and_ps(_mm_cmple_ps(a_[kMinX], _mm_loadu_ps(column_[kMaxX] + q)),
                                _mm_cmple_ps(_mm_loadu_ps(column_[kMinX] + q), a_[kMaxX]));
        all = _mm_and_ps(all, _mm_cmple_ps(a_[kMinY], _mm_loadu_ps(column_[kMaxY] + q)));
        all = _mm_and_ps(all, _mm_cmple_ps(_mm_loadu_ps(column_[kMinY] + q), a_[kMaxY]));
        all = _mm_and_ps(all, _mm_cmple_ps(a_[kMinZ], _mm_loadu_ps(column_[kMaxZ] + q)));
        all = _mm_and_ps(all, _mm_cmple_ps(_mm_loadu_ps(column_[kMinZ] + q), a_[kMaxZ]));
        return static_cast<uint32_t>(_mm_movemask_ps(all));
    }
    __m128 a_[kCoordinates];
#else
    float a_[kCoordinates];
#endif
    const float* column_[kCoordinates];
};

// Bit k set = bit `Bit` of flags[q0 + k] is set, for the kBlock words from q0.
template <int Bit>
inline uint32_t block_flag_bits(const uint32_t* flags, std::size_t q0) {
#if defined(__SSE2__)
    uint32_t bits = 0;
    for (std::size_t half = 0; half < BoxColumns::kBlock; half += 4) {
        const __m128i words = _mm_loadu_si128(reinterpret_cast<const __m128i*>(flags + q0 + half));
        // The flag into each word's sign bit, gathered by movemask.
        bits |= static_cast<uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(_mm_slli_epi32(words, 31 - Bit)))) << half;
    }
    return bits;
#else
    uint32_t bits = 0;
    for (std::size_t k = 0; k < BoxColumns::kBlock; ++k) bits |= ((flags[q0 + k] >> Bit) & 1u) << k;
    return bits;
#endif
}

// The bits of a block from q0 that lie before `end`.
inline uint32_t block_mask_before(std::size_t q0, std::size_t end) {
    const std::size_t inside = end - q0;
    return inside >= BoxColumns::kBlock ? (1u << BoxColumns::kBlock) - 1 : (1u << inside) - 1;
}

}  // namespace cdvp
