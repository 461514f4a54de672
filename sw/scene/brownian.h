// Brownian motion: boxes spread uniformly through a cube, each jumping a
// large random step along every axis every frame, so a frame keeps nothing
// of the last one's order (no frame-to-frame coherence for an incremental
// broad phase to reuse).
#pragma once

#include "sw/scene/kinematic_scene.h"

namespace cdvp {

struct BrownianConfig : KinematicConfig {
    // Each frame, each centre coordinate steps by a uniform draw in
    // [-jump * span, jump * span], span being the room its box has along
    // that axis, and is mirrored at the walls. 1: positions all but redrawn.
    double jump = 1.0;
    // The boxes' volume / the cube's, as the spheres' (SpheresConfig::volume_fraction).
    double volume_fraction = 0.15;
};

class BrownianScene : public KinematicScene {
public:
    // Throws InputError for a config out of range.
    explicit BrownianScene(const BrownianConfig& config);
    Frame next() override;
    std::size_t max_boxes(std::size_t) const override { return boxes_.size(); }
    double edge() const { return edge_; }  // the cube is [0, edge]^3

private:
    BrownianConfig config_;
    SceneRng rng_;
    double edge_ = 0.0;
    std::vector<MovingBox> boxes_;
    uint64_t next_number_ = 0;
};

}  // namespace cdvp
