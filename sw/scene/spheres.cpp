#include "sw/scene/spheres.h"

#include "sw/scene/scene_random.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace cdvp {

namespace {

// Bit-identical on every platform: see scene_random.h.

constexpr double kPi = 3.141592653589793;

void check(bool ok, const std::string& what) {
    if (!ok) {
        throw InputError("spheres scene: " + what);
    }
}

}  // namespace

SpheresPlacement place_spheres(const SpheresConfig& c) {
    check(std::isfinite(c.radius_min) && std::isfinite(c.radius_max) &&
              c.radius_min >= 0.0 && c.radius_max > 0.0 && c.radius_min <= c.radius_max,
          "expected 0 <= radius_min <= radius_max, radius_max > 0");
    check(c.volume_fraction > 0.0 && c.volume_fraction < 1.0,
          "expected volume_fraction in (0, 1)");
    check(std::isfinite(c.max_speed) && c.max_speed >= 0.0, "expected max_speed >= 0");
    check(std::isfinite(c.dt) && c.dt >= 0.0, "expected dt >= 0");
    check(c.moving_fraction >= 0.0 && c.moving_fraction <= 1.0, "expected moving_fraction in [0, 1]");

    // E[r^3] for r uniform in [a, b] is (b^4 - a^4) / (4 (b - a)).
    double a = c.radius_min;
    double b = c.radius_max;
    double mean_r3 = a == b ? a * a * a : (b * b * b * b - a * a * a * a) / (4.0 * (b - a));
    double volume = static_cast<double>(c.objects) * (4.0 / 3.0) * kPi * mean_r3 /
                    c.volume_fraction;
    SpheresPlacement placement;
    placement.edge = std::max(volume > 0.0 ? exact_cube_root(volume) : 0.0, 2.0 * b);

    SceneRng rng(c.seed);
    placement.spheres.resize(c.objects);
    for (SphereState& s : placement.spheres) {
        s.radius = a + (b - a) * rng.unit();
        double hi = centre_limit(placement.edge, s.radius);
        for (double& x : s.centre) {
            x = std::min(s.radius + (hi - s.radius) * rng.unit(), hi);
        }
        // Uniform in the unit ball by rejection from the cube [-1, 1)^3.
        double len2 = 0.0;
        do {
            for (double& v : s.velocity) {
                v = 2.0 * rng.unit() - 1.0;
            }
            len2 = s.velocity[0] * s.velocity[0] + s.velocity[1] * s.velocity[1] +
                   s.velocity[2] * s.velocity[2];
        } while (len2 > 1.0);
        for (double& v : s.velocity) {
            v *= c.max_speed;
        }
    }
    // Sphere k moves when floor((k + 1) f) > floor(k f): floor(N f) of them,
    // evenly spread; the draws above stay the same whatever f is.
    for (std::size_t k = 0; k < placement.spheres.size(); ++k) {
        SphereState& s = placement.spheres[k];
        s.fixed = !in_even_share(k, c.moving_fraction);
        if (s.fixed) s.velocity = {0.0, 0.0, 0.0};
    }
    return placement;
}

void move_sphere(SphereState& s, double hi, double dt) {
    for (int axis = 0; axis < 3; ++axis) {
        bounce(s.centre[axis], s.velocity[axis], s.radius, hi, dt);
    }
}

Frame spheres_frame(uint64_t number, const std::vector<SphereState>& spheres) {
    Frame frame;
    frame.number = number;
    frame.ids.resize(spheres.size());
    frame.boxes.resize(spheres.size());
    for (std::size_t k = 0; k < spheres.size(); ++k) {
        const SphereState& s = spheres[k];
        frame.ids[k] = k;
        for (int axis = 0; axis < 3; ++axis) {
            frame.boxes[k].min[axis] = s.centre[axis] - s.radius;
            frame.boxes[k].max[axis] = s.centre[axis] + s.radius;
        }
    }
    return frame;
}

SpheresScene::SpheresScene(const SpheresConfig& config) : config_(config) {
    SpheresPlacement placement = place_spheres(config_);
    edge_ = placement.edge;
    spheres_ = std::move(placement.spheres);
    for (const SphereState& s : spheres_) {
        hi_.push_back(centre_limit(edge_, s.radius));
    }
}

void SpheresScene::advance() {
    for (std::size_t k = 0; k < spheres_.size(); ++k) {
        move_sphere(spheres_[k], hi_[k], config_.dt);
    }
}

Frame SpheresScene::next() {
    if (next_number_ > 0) {
        advance();
    }
    return spheres_frame(next_number_++, spheres_);
}

}  // namespace cdvp
