// Box pruning's sweep eight floats at a time: this file alone is compiled
// with -mavx2 (sw/baselines/CMakeLists.txt) and runs only where the CPU has
// AVX2 (BoxPruningBroadPhase checks).
#include <immintrin.h>

#include <algorithm>
#include <cstdint>

#include "sw/baselines/box_pruning_kernel.h"

namespace cdvp {

namespace {

struct Avx2Lanes {
    static constexpr int kWidth = 8;
    using F = __m256;
    using M = __m256;
    static F load(const float* p) { return _mm256_loadu_ps(p); }
    static F splat(float x) { return _mm256_set1_ps(x); }
    static M le(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }  // false for NaN
    static M both(M a, M b) { return _mm256_and_ps(a, b); }
    static unsigned bits(M m) { return static_cast<unsigned>(_mm256_movemask_ps(m)); }
};

#include "sw/baselines/box_pruning_sweep.inc"

}  // namespace

void prune_sweep_avx2(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out, uint64_t max_pairs) {
    sweep_with<Avx2Lanes>(boxes, first, last, out, max_pairs);
}

}  // namespace cdvp
