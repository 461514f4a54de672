#include "sw/scene/brownian.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

BrownianScene::BrownianScene(const BrownianConfig& config) : config_(config), rng_(config.seed) {
    check_scene(config.jump >= 0.0 && config.jump <= 1.0, "brownian", "expected jump in [0, 1]");
    check_scene(config.volume_fraction > 0.0 && config.volume_fraction < 1.0, "brownian",
                "expected volume_fraction in (0, 1)");
    const double volume = static_cast<double>(config.objects) * kMeanBoxVolume / config.volume_fraction;
    edge_ = std::max(volume > 0.0 ? exact_cube_root(volume) : 0.0, kMaxExtent);
    const std::array<double, 3> room{edge_, edge_, edge_};
    boxes_.reserve(config.objects);
    for (std::size_t k = 0; k < config.objects; ++k) {
        const std::array<double, 3> extents = draw_extents(rng_);
        boxes_.push_back(place_box(rng_, extents, room));
    }
}

Frame BrownianScene::next() {
    if (next_number_ > 0) {
        // A jump is a step of one unit of time at a velocity drawn afresh.
        for (MovingBox& box : boxes_) {
            for (int axis = 0; axis < 3; ++axis) {
                const double span = box.hi[axis] - box.half[axis];
                box.velocity[axis] = (2.0 * rng_.unit() - 1.0) * config_.jump * span;
            }
            move_box(box, 1.0);
        }
    }
    return moving_frame(next_number_++, boxes_);
}

}  // namespace cdvp
