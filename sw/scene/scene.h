// Scenes as users give them: boxes in double precision, grouped in frames.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/common/user_text.h"

namespace cdvp {

// A box in scene units (double). Bounds may be +-inf; never NaN; min <= max.
struct Box {
    double min[3];
    double max[3];
};

// One frame of a scene: ids[k] names boxes[k]. Ids are unique within a frame.
struct Frame {
    uint64_t number = 0;
    std::vector<uint64_t> ids;
    std::vector<Box> boxes;
};


}  // namespace cdvp
