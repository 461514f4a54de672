// Scenes as users give them: boxes in double precision, grouped in frames.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

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

// Bad user input (a file, a flag). what() is one line: "FILE:LINE: message"
// for file input, so the CLI prints it as is and exits with status 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace cdvp
