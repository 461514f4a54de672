#include "sw/scene/heavy.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

namespace {

// A large box's extents: longest extent `length`, thickness a small box's
// mean extent. One of three kinds, a third each.
std::array<double, 3> large_extents(SceneRng& rng, double length) {
    const double thick = kMeanExtent;
    const double across = std::max(length * rng.uniform(0.5, 1.0), thick);
    switch (rng.below(3)) {
        case 0: return {length, across, thick};              // a slab: floor or platform
        case 1:                                              // a wall, along x or y
            return rng.below(2) == 0 ? std::array<double, 3>{length, thick, across / 2.0}
                                     : std::array<double, 3>{thick, length, across / 2.0};
        default: return {length, across / 2.0, across / 2.0};  // a ramp rising along x
    }
}

}  // namespace

HeavyScene::HeavyScene(const HeavyConfig& config) : config_(config) {
    check_scene(std::isfinite(config.size_ratio) && config.size_ratio >= 1.0, "heavy", "expected size_ratio >= 1");
    check_scene(config.large_fraction >= 0.0 && config.large_fraction <= 1.0, "heavy",
                "expected large_fraction in [0, 1]");
    check_scene(config.volume_fraction > 0.0 && config.volume_fraction < 1.0, "heavy",
                "expected volume_fraction in (0, 1)");
    check_scene(std::isfinite(config.max_speed) && config.max_speed >= 0.0, "heavy", "expected max_speed >= 0");
    check_scene(std::isfinite(config.dt) && config.dt >= 0.0, "heavy", "expected dt >= 0");
    std::size_t small = 0;
    for (std::size_t k = 0; k < config.objects; ++k) small += is_large(k) ? 0 : 1;
    const double longest = config.size_ratio * kMeanExtent;
    const double volume = static_cast<double>(small) * kMeanBoxVolume / config.volume_fraction;
    const bool any_large = small < config.objects;
    edge_ = std::max({volume > 0.0 ? exact_cube_root(volume) : 0.0, any_large ? longest : 0.0, kMaxExtent});
    const std::array<double, 3> room{edge_, edge_, edge_};
    SceneRng rng(config.seed);
    boxes_.reserve(config.objects);
    for (std::size_t k = 0; k < config.objects; ++k) {
        if (is_large(k)) {
            boxes_.push_back(place_box(rng, large_extents(rng, longest * rng.uniform(0.75, 1.0)), room));
            continue;
        }
        MovingBox box = place_box(rng, draw_extents(rng), room);
        // Uniform in the unit ball by rejection from the cube [-1, 1)^3.
        double len2 = 0.0;
        do {
            for (double& v : box.velocity) v = 2.0 * rng.unit() - 1.0;
            len2 = box.velocity[0] * box.velocity[0] + box.velocity[1] * box.velocity[1] +
                   box.velocity[2] * box.velocity[2];
        } while (len2 > 1.0);
        for (double& v : box.velocity) v *= config.max_speed;
        boxes_.push_back(box);
    }
}

Frame HeavyScene::next() {
    if (next_number_ > 0) {
        for (MovingBox& box : boxes_) move_box(box, config_.dt);  // the large ones stand still
    }
    return moving_frame(next_number_++, boxes_);
}

}  // namespace cdvp
