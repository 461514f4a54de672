#include "models/common/pair_count.h"

#include <algorithm>
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
    return boxes.size() < kGridFrom ? count_by_sweep(boxes) : count_by_grid(boxes);
}

uint64_t PairCounter::count_by_sweep(const std::vector<FloatBox>& boxes) {
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

uint64_t PairCounter::count_by_grid(const std::vector<FloatBox>& boxes) {
    valid_.clear();
    for (uint32_t k = 0; k < boxes.size(); ++k) {
        if (!has_nan(boxes[k])) valid_.push_back(k);  // a NaN box meets nothing
    }
    const std::size_t n = valid_.size();
    if (n < 2) return 0;
    // Per axis the finite span of the bounds and the boxes' mean extent. A
    // box is filed by [lo, hi] = its bounds in order: a box with min > max
    // meets only boxes covering [max, min], which share its cells.
    double low[3], per_cell[3];  // cells per unit of length
    uint32_t cells[3];
    const double most_cells = 2.0 * static_cast<double>(n);
    for (int axis = 0; axis < 3; ++axis) {
        double lo = INFINITY, hi = -INFINITY, extent = 0;
        std::size_t finite = 0;
        for (uint32_t k : valid_) {
            const double a = boxes[k].min[axis], b = boxes[k].max[axis];
            // No NaN is left, so plain comparisons order every bound (and avoid libm calls).
            const bool finite_a = a > -INFINITY && a < INFINITY, finite_b = b > -INFINITY && b < INFINITY;
            if (finite_a) lo = a < lo ? a : lo, hi = a > hi ? a : hi;
            if (finite_b) lo = b < lo ? b : lo, hi = b > hi ? b : hi;
            if (finite_a && finite_b) extent += a < b ? b - a : a - b, ++finite;
        }
        if (!(hi > lo)) lo = hi = 0;
        const double mean = finite > 0 ? extent / static_cast<double>(finite) : 0;
        const double wanted = mean > 0 ? std::floor((hi - lo) / mean) + 1 : 1;
        cells[axis] = static_cast<uint32_t>(std::clamp(wanted, 1.0, std::cbrt(most_cells)));
        low[axis] = lo;
        per_cell[axis] = hi > lo ? cells[axis] / (hi - lo) : 0.0;
    }
    // Clamped before the conversion (so -inf and +inf land in the end cells);
    // truncation is the floor of a value at or above 0.
    const auto cell_of = [&](int axis, double v) {
        const double at = (v - low[axis]) * per_cell[axis];
        const double last = static_cast<double>(cells[axis] - 1);
        return static_cast<uint32_t>(at > 0 ? (at < last ? at : last) : 0.0);
    };
    // Each box's cells; one covering more than kMostCells is tested against every box.
    constexpr uint64_t kMostCells = 64;
    ranges_.resize(n);
    big_.clear();
    const std::size_t grid_cells = std::size_t{cells[0]} * cells[1] * cells[2];
    cell_start_.assign(grid_cells + 1, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const FloatBox& box = boxes[valid_[k]];
        CellRange& r = ranges_[k];
        uint64_t covered = 1;
        for (int axis = 0; axis < 3; ++axis) {
            const float a = box.min[axis], b = box.max[axis];
            r.low[axis] = cell_of(axis, a < b ? a : b);
            r.high[axis] = cell_of(axis, a < b ? b : a);
            covered *= r.high[axis] - r.low[axis] + 1;
        }
        if (covered > kMostCells) {
            big_.push_back(static_cast<uint32_t>(k));
            r.low[0] = 1, r.high[0] = 0;  // files nowhere
            continue;
        }
        for (uint32_t x = r.low[0]; x <= r.high[0]; ++x)
            for (uint32_t y = r.low[1]; y <= r.high[1]; ++y)
                for (uint32_t z = r.low[2]; z <= r.high[2]; ++z) ++cell_start_[(x * cells[1] + y) * cells[2] + z + 1];
    }
    for (std::size_t c = 0; c < grid_cells; ++c) cell_start_[c + 1] += cell_start_[c];
    cell_boxes_.resize(cell_start_[grid_cells]);
    scratch_.assign(cell_start_.begin(), cell_start_.end() - 1);  // each cell's next free place
    for (std::size_t k = 0; k < n; ++k) {
        const CellRange& r = ranges_[k];
        for (uint32_t x = r.low[0]; x <= r.high[0] && r.low[0] <= r.high[0]; ++x)
            for (uint32_t y = r.low[1]; y <= r.high[1]; ++y)
                for (uint32_t z = r.low[2]; z <= r.high[2]; ++z)
                    cell_boxes_[scratch_[(x * cells[1] + y) * cells[2] + z]++] = static_cast<uint32_t>(k);
    }
    // A pair is counted in the cell of its boxes' larger low corners only: both cover it.
    uint64_t pairs = 0;
    for (uint32_t x = 0; x < cells[0]; ++x)
        for (uint32_t y = 0; y < cells[1]; ++y)
            for (uint32_t z = 0; z < cells[2]; ++z) {
                const std::size_t c = (std::size_t{x} * cells[1] + y) * cells[2] + z;
                for (uint32_t p = cell_start_[c]; p < cell_start_[c + 1]; ++p) {
                    const CellRange& a = ranges_[cell_boxes_[p]];
                    const FloatBox& box_a = boxes[valid_[cell_boxes_[p]]];
                    for (uint32_t q = p + 1; q < cell_start_[c + 1]; ++q) {
                        const CellRange& b = ranges_[cell_boxes_[q]];
                        if (std::max(a.low[0], b.low[0]) != x || std::max(a.low[1], b.low[1]) != y ||
                            std::max(a.low[2], b.low[2]) != z) {
                            continue;
                        }
                        pairs += overlaps(box_a, boxes[valid_[cell_boxes_[q]]]);
                    }
                }
            }
    // The big boxes: against every box, each pair of two big ones once.
    for (std::size_t b = 0; b < big_.size(); ++b) {
        const FloatBox& box = boxes[valid_[big_[b]]];
        for (std::size_t k = 0; k < n; ++k) {
            const bool other_big = ranges_[k].low[0] > ranges_[k].high[0];
            if (other_big && k <= big_[b]) continue;
            pairs += overlaps(box, boxes[valid_[k]]);
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
