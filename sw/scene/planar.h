// A planar spread: every box stands on a wide floor, its bottom within a
// thin band above it, and moves in the plane only, bouncing off the floor's
// edges (a strategy game's units, a crowd, traffic). The floor grows with
// the object count so the boxes cover the same share of it.
#pragma once

#include "sw/scene/kinematic_scene.h"

namespace cdvp {

struct PlanarConfig : KinematicConfig {
    // The floor's length (x) over its width (y): 1 a square, more a corridor.
    double aspect = 1.0;
    // The boxes' footprints / the floor's area (overlaps counted twice).
    double coverage = 0.25;
    // Each box's bottom lies uniform in [0, height_band] above the floor.
    double height_band = 0.25;
    // Velocities uniform in the disc of this radius, in the plane.
    double max_speed = 4.0;
};

class PlanarScene : public KinematicScene {
public:
    // Throws InputError for a config out of range.
    explicit PlanarScene(const PlanarConfig& config);
    Frame next() override;
    std::size_t max_boxes(std::size_t) const override { return boxes_.size(); }
    // The floor is [0, length] x [0, width] at z = 0.
    double length() const { return length_; }
    double width() const { return width_; }

private:
    PlanarConfig config_;
    double length_ = 0.0, width_ = 0.0;
    std::vector<MovingBox> boxes_;
    uint64_t next_number_ = 0;
};

}  // namespace cdvp
