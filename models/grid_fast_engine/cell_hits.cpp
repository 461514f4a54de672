#include "models/grid_fast_engine/cell_hits.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define CDVP_CELL_HITS_WIDE 1
#endif

namespace cdvp {

namespace {

// The columns after r that the one-cell rule may keep beside row r.
inline uint64_t partners_of(uint32_t r, uint64_t all, const uint64_t (&starts)[3]) {
    uint64_t partners = all & (~uint64_t{0} << (r + 1));
    for (uint32_t a = 0; a < 3; ++a) partners &= (starts[a] >> r & 1) != 0 ? all : starts[a];
    return partners;
}

inline uint64_t all_of(uint32_t n) { return ~uint64_t{0} >> (64 - n); }

// Four columns a compare (BlockTest).
void four_at_a_time(const BoxColumns& columns, uint32_t n, const uint64_t (&starts)[3], uint64_t* row_hits) {
    const uint64_t all = all_of(n);
    for (uint32_t r = 0; r + 1 < n; ++r) {
        uint64_t partners = partners_of(r, all, starts);
        int32_t row[kCoordinates];
        columns.get(r, row);
        const BlockTest test(columns, row);
        // Groups of four columns from each next partner.
        uint64_t hits = 0;
        while (partners != 0) {
            const auto q0 = static_cast<uint32_t>(__builtin_ctzll(partners));
            const uint32_t wanted = static_cast<uint32_t>(partners >> q0) & 0xFu;
            hits |= uint64_t{test.hits(q0) & wanted} << q0;
            partners &= ~(uint64_t{0xF} << q0);
        }
        row_hits[r] = hits;
    }
}

#if defined(CDVP_CELL_HITS_WIDE)
__attribute__((target("avx2"))) inline __m256i eight_from(const int32_t* column, uint32_t q) {
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(column + q));
}

__attribute__((target("avx512f"))) inline __m512i sixteen_from(const int32_t* column, uint32_t q) {
    return _mm512_loadu_si512(column + q);
}

// Eight columns a compare: a miss is a.min > b.max or b.min > a.max on some axis.
__attribute__((target("avx2"))) void eight_at_a_time(const BoxColumns& columns, uint32_t n,
                                                     const uint64_t (&starts)[3], uint64_t* row_hits) {
    const uint64_t all = all_of(n);
    const int32_t* column[kCoordinates];
    for (uint32_t c = 0; c < kCoordinates; ++c) column[c] = columns.bound[c].data();
    for (uint32_t r = 0; r + 1 < n; ++r) {
        uint64_t partners = partners_of(r, all, starts);
        __m256i a[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) a[c] = _mm256_set1_epi32(column[c][r]);
        uint64_t hits = 0;
        while (partners != 0) {
            const auto q0 = static_cast<uint32_t>(__builtin_ctzll(partners));
            __m256i miss = _mm256_or_si256(_mm256_cmpgt_epi32(a[kMinX], eight_from(column[kMaxX], q0)),
                                           _mm256_cmpgt_epi32(eight_from(column[kMinX], q0), a[kMaxX]));
            miss = _mm256_or_si256(miss, _mm256_cmpgt_epi32(a[kMinY], eight_from(column[kMaxY], q0)));
            miss = _mm256_or_si256(miss, _mm256_cmpgt_epi32(eight_from(column[kMinY], q0), a[kMaxY]));
            miss = _mm256_or_si256(miss, _mm256_cmpgt_epi32(a[kMinZ], eight_from(column[kMaxZ], q0)));
            miss = _mm256_or_si256(miss, _mm256_cmpgt_epi32(eight_from(column[kMinZ], q0), a[kMaxZ]));
            const auto found = static_cast<uint32_t>(~_mm256_movemask_ps(_mm256_castsi256_ps(miss))) & 0xFFu;
            hits |= uint64_t{found} << q0 & partners;
            partners &= ~(uint64_t{0xFF} << q0);
        }
        row_hits[r] = hits;
    }
}

// Sixteen columns a compare, the misses as a mask.
__attribute__((target("avx512f"))) void sixteen_at_a_time(const BoxColumns& columns, uint32_t n,
                                                         const uint64_t (&starts)[3], uint64_t* row_hits) {
    const uint64_t all = all_of(n);
    const int32_t* column[kCoordinates];
    for (uint32_t c = 0; c < kCoordinates; ++c) column[c] = columns.bound[c].data();
    for (uint32_t r = 0; r + 1 < n; ++r) {
        uint64_t partners = partners_of(r, all, starts);
        __m512i a[kCoordinates];
        for (uint32_t c = 0; c < kCoordinates; ++c) a[c] = _mm512_set1_epi32(column[c][r]);
        uint64_t hits = 0;
        while (partners != 0) {
            const auto q0 = static_cast<uint32_t>(__builtin_ctzll(partners));
            const __mmask16 miss = _mm512_cmpgt_epi32_mask(a[kMinX], sixteen_from(column[kMaxX], q0)) |
                                   _mm512_cmpgt_epi32_mask(sixteen_from(column[kMinX], q0), a[kMaxX]) |
                                   _mm512_cmpgt_epi32_mask(a[kMinY], sixteen_from(column[kMaxY], q0)) |
                                   _mm512_cmpgt_epi32_mask(sixteen_from(column[kMinY], q0), a[kMaxY]) |
                                   _mm512_cmpgt_epi32_mask(a[kMinZ], sixteen_from(column[kMaxZ], q0)) |
                                   _mm512_cmpgt_epi32_mask(sixteen_from(column[kMinZ], q0), a[kMaxZ]);
            hits |= uint64_t{static_cast<uint16_t>(~miss)} << q0 & partners;
            partners &= ~(uint64_t{0xFFFF} << q0);
        }
        row_hits[r] = hits;
    }
}
#endif

}  // namespace

std::vector<CellHitsWidth> cell_hits_widths() {
    std::vector<CellHitsWidth> widths{{4, four_at_a_time, true}};
#if defined(CDVP_CELL_HITS_WIDE)
    __builtin_cpu_init();
    widths.push_back({8, eight_at_a_time, __builtin_cpu_supports("avx2") != 0});
    widths.push_back({16, sixteen_at_a_time, __builtin_cpu_supports("avx512f") != 0});
#endif
    return widths;
}

void masked_cell_hits(const BoxColumns& columns, uint32_t n, const uint64_t (&starts)[3], uint64_t* row_hits) {
    // The widest width the CPU runs, chosen at the first call.
    static const CellHits widest = [] {
        CellHits chosen = nullptr;
        for (const CellHitsWidth& width : cell_hits_widths()) {
            if (width.runs) chosen = width.hits;
        }
        return chosen;
    }();
    widest(columns, n, starts, row_hits);
}

}  // namespace cdvp
