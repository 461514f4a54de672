#include "sw/baselines/box_pruning.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>

#include "sw/baselines/box_bounds.h"

#if defined(__x86_64__) || defined(__i386__)
#include <emmintrin.h>
#endif

namespace cdvp {

namespace {

struct ScalarLanes {
    static constexpr int kWidth = 1;
    using F = float;
    using M = unsigned;
    static F load(const float* p) { return *p; }
    static F splat(float x) { return x; }
    static M le(F a, F b) { return a <= b ? 1u : 0u; }
    static M both(M a, M b) { return a & b; }
    static unsigned bits(M m) { return m; }
};

#if defined(__x86_64__) || defined(__i386__)
struct Sse2Lanes {
    static constexpr int kWidth = 4;
    using F = __m128;
    using M = __m128;
    static F load(const float* p) { return _mm_loadu_ps(p); }
    static F splat(float x) { return _mm_set1_ps(x); }
    static M le(F a, F b) { return _mm_cmple_ps(a, b); }  // false for NaN
    static M both(M a, M b) { return _mm_and_ps(a, b); }
    static unsigned bits(M m) { return static_cast<unsigned>(_mm_movemask_ps(m)); }
};
#endif

#include "sw/baselines/box_pruning_sweep.inc"

// Floats ordered as unsigned integers: negative ones (sign set) reversed,
// positive ones above them. -0 sorts just below +0, which compare equal.
uint32_t sort_key(float x) {
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

// The widest SIMD sweep this CPU runs.
PruneSweep widest_sweep(int& width) {
#if defined(__x86_64__) || defined(__i386__)
    if (__builtin_cpu_supports("avx2")) return width = 8, &prune_sweep_avx2;
    return width = 4, &prune_sweep_sse2;
#else
    return width = 1, &prune_sweep_scalar;
#endif
}

}  // namespace

void prune_sweep_scalar(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out, uint64_t max_pairs) {
    sweep_with<ScalarLanes>(boxes, first, last, out, max_pairs);
}

#if defined(__x86_64__) || defined(__i386__)
void prune_sweep_sse2(const PruneArrays& boxes, uint32_t first, uint32_t last, PairList& out, uint64_t max_pairs) {
    sweep_with<Sse2Lanes>(boxes, first, last, out, max_pairs);
}
#endif

BoxPruningBroadPhase::BoxPruningBroadPhase(unsigned threads, bool multi_threaded)
    : multi_threaded_(multi_threaded),
      width_(1),
      sweep_(widest_sweep(width_)),
      pool_(multi_threaded ? (threads == 0 ? machine_threads() : threads) : 1),
      found_(pool_.size()) {}

// A least-significant-digit radix sort of the keys, 11 bits a pass (three
// passes; a pass whose digit every key shares is skipped), then the boxes'
// bounds copied in that order.
void BoxPruningBroadPhase::sort_boxes(const std::vector<FloatBox>& boxes) {
    valid_boxes(boxes, valid_);
    axis_ = widest_axis(boxes, valid_);
    const int axis = axis_;
    const std::size_t n = valid_.size();
    keys_.resize(n);
    order_.resize(n);
    scratch_keys_.resize(n);
    scratch_order_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const FloatBox& b = boxes[valid_[k]];
        keys_[k] = sort_key(std::min(b.min[axis], b.max[axis]));
        order_[k] = valid_[k];
    }
    constexpr int kBits = 11;
    constexpr uint32_t kBuckets = 1u << kBits;
    uint32_t count[kBuckets];
    for (int shift = 0; shift < 32; shift += kBits) {
        std::fill(count, count + kBuckets, 0u);
        for (const uint32_t key : keys_) ++count[(key >> shift) & (kBuckets - 1)];
        if (n == 0 || count[(keys_[0] >> shift) & (kBuckets - 1)] == n) continue;
        uint32_t sum = 0;
        for (uint32_t& c : count) sum += std::exchange(c, sum);
        for (std::size_t k = 0; k < n; ++k) {
            const uint32_t at = count[(keys_[k] >> shift) & (kBuckets - 1)]++;
            scratch_keys_[at] = keys_[k];
            scratch_order_[at] = order_[k];
        }
        keys_.swap(scratch_keys_);
        order_.swap(scratch_order_);
    }
    const std::size_t padded = n + 8;
    key_.assign(padded, std::numeric_limits<float>::quiet_NaN());
    for (int a = 0; a < 3; ++a) {
        min_[a].assign(padded, std::numeric_limits<float>::quiet_NaN());
        max_[a].assign(padded, std::numeric_limits<float>::quiet_NaN());
    }
    for (std::size_t k = 0; k < n; ++k) {
        const FloatBox& b = boxes[order_[k]];
        key_[k] = std::min(b.min[axis], b.max[axis]);
        for (int a = 0; a < 3; ++a) min_[a][k] = b.min[a], max_[a][k] = b.max[a];
    }
}

void BoxPruningBroadPhase::find_pairs(const std::vector<FloatBox>& boxes, PairList& out) {
    out.clear();
    sort_boxes(boxes);
    const PruneArrays arrays{key_.data(),
                             {min_[0].data(), min_[1].data(), min_[2].data()},
                             {max_[0].data(), max_[1].data(), max_[2].data()},
                             order_.data(),
                             static_cast<uint32_t>(valid_.size()),
                             axis_};
    found_.clear();
    next_.store(0);
    const uint64_t budget = budget_.max_pairs();
    pool_.run([&](unsigned thread) {
        // One thread sweeps in one go; several take chunks, so a crowded
        // stretch of the axis spreads over them.
        const uint32_t chunk = pool_.size() == 1 ? std::max<uint32_t>(arrays.count, 1) : kChunk;
        while (true) {
            const uint32_t first = next_.fetch_add(chunk, std::memory_order_relaxed);
            if (first >= arrays.count) return;
            sweep_(arrays, first, std::min(first + chunk, arrays.count), found_.list(thread), budget);
            if (!found_.report(thread, budget_)) return;
        }
    });
    found_.join(out, budget_);
}

}  // namespace cdvp
