// Where `cdvp run` gets its frames: a trace file or a generated scene.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sw/scene/scene.h"
#include "sw/scene/spheres.h"

namespace cdvp {

class FrameSource {
public:
    virtual ~FrameSource() = default;
    virtual std::optional<Frame> next() = 0;
    virtual std::size_t frame_count() const = 0;
    // The most boxes any frame holds: the board's memory depth.
    virtual std::size_t max_objects() const = 0;
    // For the report: what the frames come from.
    virtual std::string describe() const = 0;
};

// All frames of a trace file, parsed and checked up front (bad input fails
// before anything is simulated or written).
std::unique_ptr<FrameSource> trace_source(const std::string& path);

// A spheres scene generated frame by frame (no frame is kept).
std::unique_ptr<FrameSource> spheres_source(const SpheresConfig& config, std::size_t frames);

}  // namespace cdvp
