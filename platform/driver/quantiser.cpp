#include "platform/driver/quantiser.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

Quantiser::Quantiser(NumberFormat format, const std::vector<FloatBox>& boxes)
    : format_(format), top_(static_cast<double>(format.max_code())), low_{}, high_{}, scale_{} {
    if (format.is_float()) return;  // the words are the floats
    for (uint32_t axis = 0; axis < 3; ++axis) {
        double lo = INFINITY, hi = -INFINITY;
        for (const FloatBox& box : boxes) {
            if (std::isfinite(box.min[axis])) lo = std::min<double>(lo, box.min[axis]);
            if (std::isfinite(box.max[axis])) hi = std::max<double>(hi, box.max[axis]);
        }
        low_[axis] = lo;
        high_[axis] = hi;
        // hi <= lo, or no finite bound: every finite value maps to 0.
        scale_[axis] = hi > lo ? top_ / (hi - lo) : 0.0;
        if (!(hi > lo)) low_[axis] = std::isfinite(lo) ? lo : 0.0;
    }
}

void Quantiser::write_column(const std::vector<FloatBox>& boxes, uint32_t c, uint32_t* words) const {
    const std::size_t n = boxes.size();
    if (format_.is_float()) {
        for (std::size_t i = 0; i < n; ++i) words[i] = ComparisonUnit::as_bits(c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3]);
    } else if (c < 3) {
        for (std::size_t i = 0; i < n; ++i) words[i] = min_code(c, boxes[i].min[c]);
    } else {
        for (std::size_t i = 0; i < n; ++i) words[i] = max_code(c - 3, boxes[i].max[c - 3]);
    }
}

uint32_t Quantiser::clamp(double code) const { return static_cast<uint32_t>(std::min(std::max(code, 0.0), top_)); }

uint32_t Quantiser::min_code(uint32_t axis, float x) const {
    if (std::isnan(x)) return 0;
    if (std::isinf(x)) return x > 0 ? static_cast<uint32_t>(top_) : 0;
    return clamp(std::floor(scaled(axis, x)));
}

uint32_t Quantiser::max_code(uint32_t axis, float x) const {
    if (std::isnan(x)) return static_cast<uint32_t>(top_);
    if (std::isinf(x)) return x > 0 ? static_cast<uint32_t>(top_) : 0;
    return clamp(std::ceil(scaled(axis, x)));
}

}  // namespace cdvp
