#include "sw/scene/conversion.h"

#include <cmath>
#include <limits>

namespace cdvp {

// (float)v rounds to nearest (in whatever rounding mode is current, it lands
// on one of the two neighbouring floats); one nextafterf step fixes the side.
// Only IEEE comparisons are used, so denormals are handled as long as the
// process does not run with flush-to-zero / denormals-are-zero enabled.

float round_down_to_float(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) > v) {
        f = std::nextafterf(f, -std::numeric_limits<float>::infinity());
    }
    return f;
}

float round_up_to_float(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) {
        f = std::nextafterf(f, std::numeric_limits<float>::infinity());
    }
    return f;
}

FloatBox to_float_box(const Box& b) {
    FloatBox f;
    for (int axis = 0; axis < 3; ++axis) {
        f.min[axis] = round_down_to_float(b.min[axis]);
        f.max[axis] = round_up_to_float(b.max[axis]);
    }
    return f;
}

std::vector<FloatBox> to_float_boxes(const std::vector<Box>& boxes) {
    std::vector<FloatBox> out;
    out.reserve(boxes.size());
    for (const Box& b : boxes) {
        out.push_back(to_float_box(b));
    }
    return out;
}

}  // namespace cdvp
