// The host's side of a fixed-point board: float boxes to fixed-point codes
// over the frame's scene bounds, rounded outward so that no pair is lost.
#pragma once

#include <cstdint>
#include <vector>

#include "models/common/aabb.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/number_format/number_format.h"

namespace cdvp {

// Per axis, over the frame's scene bounds lo (the least finite min) and hi
// (the greatest finite max), with s = (2^K - 1) / (hi - lo) in double:
//   min code = floor((x - lo) * s), max code = ceil((x - lo) * s),
// clamped to [0, 2^K - 1]; -inf -> 0, +inf -> 2^K - 1; a NaN min -> 0 and a
// NaN max -> 2^K - 1 (it meets everything: extra pairs, never a lost one);
// hi <= lo (or no finite bound) maps every finite value to 0. Each step is
// monotone in x (rounded subtraction and multiplication by s >= 0, floor,
// ceil, clamp), and floor <= ceil, so a <= b in float32 implies
// code_min(a) <= code_max(b): every pair of the float32 comparison survives
// (docs/numerics.md). Under float32 the word is the float's bit pattern.
class Quantiser {
public:
    Quantiser(NumberFormat format, const std::vector<FloatBox>& boxes);

    // The word the host writes for bound c (Coordinate order) of a box.
    uint32_t word(const FloatBox& box, uint32_t c) const {
        if (format_.is_float()) return ComparisonUnit::as_bits(c < 3 ? box.min[c] : box.max[c - 3]);
        return c < 3 ? min_code(c, box.min[c]) : max_code(c - 3, box.max[c - 3]);
    }
    // Bound c of every box into words, the format chosen once.
    void write_column(const std::vector<FloatBox>& boxes, uint32_t c, uint32_t* words) const;
    uint32_t min_code(uint32_t axis, float x) const;
    uint32_t max_code(uint32_t axis, float x) const;

    double low(uint32_t axis) const { return low_[axis]; }
    double high(uint32_t axis) const { return high_[axis]; }

private:
    // (x - lo) * s for finite x, unclamped.
    double scaled(uint32_t axis, float x) const { return (static_cast<double>(x) - low_[axis]) * scale_[axis]; }
    uint32_t clamp(double code) const;

    NumberFormat format_;
    double top_;  // 2^K - 1
    double low_[3], high_[3], scale_[3];
};

}  // namespace cdvp
