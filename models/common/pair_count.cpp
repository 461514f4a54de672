#include "models/common/pair_count.h"

#include <cmath>
#include <cstring>

namespace cdvp {

namespace {

bool overlaps(const FloatBox& a, const FloatBox& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis])) return false;
    }
    return true;
}

bool has_nan(const FloatBox& box) {
    for (int axis = 0; axis < 3; ++axis) {
        if (std::isnan(box.min[axis]) || std::isnan(box.max[axis])) return true;
    }
    return false;
}

// A float's bits as an unsigned key in the float's order (-0 and +0 apart,
// which the sweep's comparisons do not mind: they compare the floats).
uint32_t order_key(float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

// The axis along which boxes overlap least often: centres spread widest
// against the boxes' mean extent.
int sweep_axis(const std::vector<FloatBox>& boxes) {
    int best = 0;
    double best_ratio = -1;
    for (int axis = 0; axis < 3; ++axis) {
        double low = INFINITY, high = -INFINITY, extent = 0;
        for (const FloatBox& box : boxes) {
            const double centre = 0.5 * (double{box.min[axis]} + double{box.max[axis]});
            low = std::fmin(low, centre);
            high = std::fmax(high, centre);
            extent += double{box.max[axis]} - double{box.min[axis]};
        }
        const double ratio = (high - low) / (extent / static_cast<double>(boxes.size()) + 1e-30);
        if (ratio > best_ratio) best_ratio = ratio, best = axis;
    }
    return best;
}

}  // namespace

uint64_t PairCounter::count(const std::vector<FloatBox>& boxes) {
    if (boxes.size() < 2) return 0;
    const int x = sweep_axis(boxes), y = (x + 1) % 3, z = (x + 2) % 3;
    order_.clear();
    keys_.clear();
    for (uint32_t k = 0; k < boxes.size(); ++k) {
        if (has_nan(boxes[k])) continue;  // every comparison with it is false
        order_.push_back(k);
        keys_.push_back(order_key(boxes[k].min[x]));
    }
    // LSD radix sort by the swept axis's minimum, a byte a pass.
    const std::size_t n = order_.size();
    scratch_.resize(n);
    scratch_keys_.resize(n);
    for (int shift = 0; shift < 32; shift += 8) {
        uint32_t start[257] = {};
        for (std::size_t k = 0; k < n; ++k) ++start[((keys_[k] >> shift) & 0xff) + 1];
        for (int b = 0; b < 256; ++b) start[b + 1] += start[b];
        for (std::size_t k = 0; k < n; ++k) {
            const uint32_t slot = start[(keys_[k] >> shift) & 0xff]++;
            scratch_[slot] = order_[k];
            scratch_keys_[slot] = keys_[k];
        }
        order_.swap(scratch_);
        keys_.swap(scratch_keys_);
    }
    // The sorted boxes side by side: the sweep reads them in order.
    bounds_.resize(6 * n);
    for (std::size_t k = 0; k < n; ++k) {
        const FloatBox& box = boxes[order_[k]];
        float* b = &bounds_[6 * k];
        b[0] = box.min[x], b[1] = box.max[x], b[2] = box.min[y], b[3] = box.max[y], b[4] = box.min[z], b[5] = box.max[z];
    }
    // Every later box whose minimum lies within this one's extent is a
    // candidate; its maximum is tested too, for boxes whose min exceeds their max.
    uint64_t pairs = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const float* a = &bounds_[6 * i];
        for (std::size_t j = i + 1; j < n; ++j) {
            const float* b = &bounds_[6 * j];
            if (!(b[0] <= a[1])) break;
            pairs += (a[0] <= b[1]) & (a[2] <= b[3]) & (b[2] <= a[3]) & (a[4] <= b[5]) & (b[4] <= a[5]);
        }
    }
    return pairs;
}

uint64_t count_pairs_brute_force(const std::vector<FloatBox>& boxes) {
    uint64_t pairs = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size(); ++j) pairs += overlaps(boxes[i], boxes[j]);
    }
    return pairs;
}

}  // namespace cdvp
