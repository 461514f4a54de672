#include "sw/scene/planar.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

PlanarScene::PlanarScene(const PlanarConfig& config) : config_(config) {
    check_scene(std::isfinite(config.aspect) && config.aspect >= 1.0, "planar", "expected aspect >= 1");
    check_scene(config.coverage > 0.0 && config.coverage <= 1.0, "planar", "expected coverage in (0, 1]");
    check_scene(std::isfinite(config.height_band) && config.height_band >= 0.0, "planar", "expected height_band >= 0");
    check_scene(std::isfinite(config.max_speed) && config.max_speed >= 0.0, "planar", "expected max_speed >= 0");
    check_scene(std::isfinite(config.dt) && config.dt >= 0.0, "planar", "expected dt >= 0");
    // Floor area A = N * mean footprint / coverage; length = sqrt(A * aspect)
    // (std::sqrt is correctly rounded: IEEE's own), neither side shorter
    // than the largest box.
    const double area = static_cast<double>(config.objects) * kMeanExtent * kMeanExtent / config.coverage;
    width_ = std::max(std::sqrt(area / config.aspect), kMaxExtent);
    length_ = std::max(area / width_, kMaxExtent);
    SceneRng rng(config.seed);
    boxes_.reserve(config.objects);
    for (std::size_t k = 0; k < config.objects; ++k) {
        const std::array<double, 3> extents = draw_extents(rng);
        const double bottom = config.height_band * rng.unit();
        MovingBox box = place_box(rng, extents, {length_, width_, bottom + extents[2]});
        box.centre[2] = bottom + box.half[2];
        box.hi[2] = box.centre[2];
        // Uniform in the unit disc by rejection from the square [-1, 1)^2.
        double len2 = 0.0;
        do {
            box.velocity[0] = 2.0 * rng.unit() - 1.0;
            box.velocity[1] = 2.0 * rng.unit() - 1.0;
            len2 = box.velocity[0] * box.velocity[0] + box.velocity[1] * box.velocity[1];
        } while (len2 > 1.0);
        box.velocity[0] *= config.max_speed;
        box.velocity[1] *= config.max_speed;
        boxes_.push_back(box);
    }
}

Frame PlanarScene::next() {
    if (next_number_ > 0) {
        for (MovingBox& box : boxes_) move_box(box, config_.dt);
    }
    return moving_frame(next_number_++, boxes_);
}

}  // namespace cdvp
