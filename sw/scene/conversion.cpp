#include "sw/scene/conversion.h"

#include <cstdint>
#include <cstring>
#include <limits>

namespace cdvp {

// (float)v rounds to nearest (in whatever rounding mode is current, it lands
// on one of the two neighbouring floats); one nextafterf step fixes the side.
// Only IEEE comparisons are used, so denormals are handled as long as the
// process does not run with flush-to-zero / denormals-are-zero enabled.

namespace {

// One float step towards +inf (up) or -inf (down) when `needed`, as
// nextafterf takes it, without a branch (a scene's conversion is six of
// these a box, and whether a bound needs its step is a coin toss): away from
// zero the bits step by one in the float's order; from either zero to the
// smallest denormal of the sign stepped to. Never asked of NaN or of the end
// it would step past.
inline float step_if(float f, bool needed, bool up) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    const bool negative = (bits >> 31) != 0;
    const bool zero = (bits << 1) == 0;
    const uint32_t away = negative == up ? bits - 1 : bits + 1;  // towards zero on a negative step up or positive step down
    const uint32_t stepped = zero ? (up ? 0x00000001u : 0x80000001u) : away;
    bits = needed ? stepped : bits;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

inline float down(double v) {
    const float f = static_cast<float>(v);
    return step_if(f, static_cast<double>(f) > v, false);
}

inline float up(double v) {
    const float f = static_cast<float>(v);
    return step_if(f, static_cast<double>(f) < v, true);
}

}  // namespace

float round_down_to_float(double v) { return down(v); }

float round_up_to_float(double v) { return up(v); }

FloatBox to_float_box(const Box& b) {
    FloatBox f;
    for (int axis = 0; axis < 3; ++axis) {
        f.min[axis] = down(b.min[axis]);
        f.max[axis] = up(b.max[axis]);
    }
    return f;
}

std::vector<FloatBox> to_float_boxes(const std::vector<Box>& boxes) {
    std::vector<FloatBox> out(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) out[k] = to_float_box(boxes[k]);
    return out;
}

}  // namespace cdvp
