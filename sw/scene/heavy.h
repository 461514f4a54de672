// Heavy-tailed sizes: a level's static geometry among debris. Most boxes are
// small debris drifting slowly through a cube; an evenly spread share are
// large static boxes, their longest extent size_ratio times a small box's
// mean extent: slabs (floors, platforms), walls, and ramps (the bounding box
// of an inclined plane). The cube holds the largest of them, and grows with
// the debris so that the debris keeps its density.
#pragma once

#include "sw/scene/kinematic_scene.h"

namespace cdvp {

struct HeavyConfig : KinematicConfig {
    // A large box's longest extent over a small box's mean extent (1.5):
    // the longest extent is uniform in [0.75, 1] x size_ratio x 1.5.
    double size_ratio = 100.0;
    // The share of boxes that are large, spread evenly over the ids (box k
    // is large when floor((k + 1) f) > floor(k f)).
    double large_fraction = 0.01;
    // The debris' volume / the cube's.
    double volume_fraction = 0.05;
    // Debris velocities uniform in the ball of this radius.
    double max_speed = 1.0;
};

class HeavyScene : public KinematicScene {
public:
    // Throws InputError for a config out of range.
    explicit HeavyScene(const HeavyConfig& config);
    Frame next() override;
    std::size_t max_boxes(std::size_t) const override { return boxes_.size(); }
    double edge() const { return edge_; }  // the cube is [0, edge]^3
    bool is_large(std::size_t k) const { return in_even_share(k, config_.large_fraction); }

private:
    HeavyConfig config_;
    double edge_ = 0.0;
    std::vector<MovingBox> boxes_;
    uint64_t next_number_ = 0;
};

}  // namespace cdvp
