// Conservative double -> float32 conversion of boxes for the board.
#pragma once

#include <vector>

#include "models/common/aabb.h"
#include "sw/scene/scene.h"

namespace cdvp {

// The largest float <= v. Values exactly representable as float (including
// -0, +-inf and denormals) are returned unchanged. Finite values below
// -FLT_MAX give -inf; values above FLT_MAX give FLT_MAX. NaN stays NaN.
float round_down_to_float(double v);

// The smallest float >= v (mirror image of round_down_to_float). Values above
// FLT_MAX give +inf. A tiny negative value (between -0x1p-149 and 0) gives -0.
float round_up_to_float(double v);

// Mins rounded down, maxes rounded up: the float box contains the double box,
// so boxes that overlap (or touch) in double still overlap in float.
FloatBox to_float_box(const Box& b);
std::vector<FloatBox> to_float_boxes(const std::vector<Box>& boxes);

}  // namespace cdvp
