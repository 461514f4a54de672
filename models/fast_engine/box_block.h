// Boxes as structure-of-arrays and the comparison unit's test on a block of them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "models/comparison_unit/comparison_unit.h"
#include "models/number_format/number_format.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cdvp {

// A stored word's key in the format's order, biased into int32 so that SSE2's
// signed compare orders it: the fast engine compares these only.
inline int32_t signed_key(NumberFormat format, uint32_t word) {
    return static_cast<int32_t>(format.key(word) ^ 0x8000'0000u);
}

// Bounds by coordinate (Coordinate order), one signed key per box. The arrays
// carry kBlock entries of padding so that a block may start at any box.
struct BoxColumns {
    static constexpr std::size_t kBlock = 4;  // a multiple of 4: BlockTest tests groups of four

    std::vector<int32_t> bound[kCoordinates];

    void resize(std::size_t boxes) {
        for (auto& column : bound) column.resize(boxes + kBlock, 0);
    }
    void set(std::size_t k, const int32_t (&bounds)[kCoordinates]) {
        for (uint32_t c = 0; c < kCoordinates; ++c) bound[c][k] = bounds[c];
    }
    void get(std::size_t k, int32_t (&bounds)[kCoordinates]) const {
        for (uint32_t c = 0; c < kCoordinates; ++c) bounds[c] = bound[c][k];
    }
};

// The comparison unit's test of box a against kBlock boxes at a time, on
// keys: bit k of hits(q0) = ComparisonUnit::lane_hit(a, box q0 + k), which for
// keys of words the format does not exclude is the comparators' own answer.
// Every comparison is evaluated (no branch).
class BlockTest {
public:
    BlockTest(const BoxColumns& boxes, const int32_t (&a)[kCoordinates]) {
        for (uint32_t c = 0; c < kCoordinates; ++c) {
            column_[c] = boxes.bound[c].data();
#if defined(__SSE2__)
            a_[c] = _mm_set1_epi32(a[c]);
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
            int32_t b[kCoordinates];
            for (uint32_t c = 0; c < kCoordinates; ++c) b[c] = column_[c][q0 + k];
            hits |= static_cast<uint32_t>(ComparisonUnit::lane_hit(a_, b)) << k;
        }
        return hits;
#endif
    }

private:
#if defined(__SSE2__)
    __m128i load(uint32_t c, std::size_t q) const {
        return _mm_loadu_si128(reinterpret_cast<const __m128i*>(column_[c] + q));
    }
    uint32_t four(std::size_t q) const {
        // A miss: a.min > b.max or b.min > a.max on some axis.
        __m128i miss = _mm_or_si128(_mm_cmpgt_epi32(a_[kMinX], load(kMaxX, q)), _mm_cmpgt_epi32(load(kMinX, q), a_[kMaxX]));
        miss = _mm_or_si128(miss, _mm_cmpgt_epi32(a_[kMinY], load(kMaxY, q)));
        miss = _mm_or_si128(miss, _mm_cmpgt_epi32(load(kMinY, q), a_[kMaxY]));
        miss = _mm_or_si128(miss, _mm_cmpgt_epi32(a_[kMinZ], load(kMaxZ, q)));
        miss = _mm_or_si128(miss, _mm_cmpgt_epi32(load(kMinZ, q), a_[kMaxZ]));
        return ~static_cast<uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(miss))) & 0xFu;
    }
    __m128i a_[kCoordinates];
#else
    int32_t a_[kCoordinates];
#endif
    const int32_t* column_[kCoordinates];
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
