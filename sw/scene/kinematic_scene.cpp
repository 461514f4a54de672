#include "sw/scene/kinematic_scene.h"

#include <algorithm>

namespace cdvp {

std::array<double, 3> draw_extents(SceneRng& rng) {
    std::array<double, 3> extents{};
    for (double& e : extents) e = rng.uniform(kMinExtent, kMaxExtent);
    return extents;
}

MovingBox place_box(SceneRng& rng, const std::array<double, 3>& extents, const std::array<double, 3>& room) {
    MovingBox box;
    for (int axis = 0; axis < 3; ++axis) {
        box.half[axis] = extents[axis] / 2.0;
        box.hi[axis] = centre_limit(room[axis], box.half[axis]);
        const double lo = box.half[axis];
        box.centre[axis] = std::min(rng.uniform(lo, box.hi[axis]), box.hi[axis]);
    }
    return box;
}

void move_box(MovingBox& box, double dt) {
    for (int axis = 0; axis < 3; ++axis) {
        bounce(box.centre[axis], box.velocity[axis], box.half[axis], box.hi[axis], dt);
    }
}

Frame moving_frame(uint64_t number, const std::vector<MovingBox>& boxes) {
    Frame frame;
    frame.number = number;
    frame.ids.resize(boxes.size());
    frame.boxes.resize(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        frame.ids[k] = k;
        for (int axis = 0; axis < 3; ++axis) {
            frame.boxes[k].min[axis] = boxes[k].centre[axis] - boxes[k].half[axis];
            frame.boxes[k].max[axis] = boxes[k].centre[axis] + boxes[k].half[axis];
        }
    }
    return frame;
}

void check_scene(bool ok, const std::string& family, const std::string& what) {
    if (!ok) throw InputError(family + " scene: " + what);
}

}  // namespace cdvp
