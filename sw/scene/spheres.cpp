#include "sw/scene/spheres.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace cdvp {

namespace {

// Results must be bit-identical on every platform: only IEEE basic
// operations are used (no libm transcendental functions, whose last bit
// varies between C libraries) and the library is built without FMA
// contraction (see CMakeLists.txt).

// xoshiro256** seeded through splitmix64, as its authors recommend.
class Rng {
public:
    explicit Rng(uint64_t seed) {
        for (uint64_t& word : s_) {
            seed += 0x9e3779b97f4a7c15ULL;
            uint64_t z = seed;
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            word = z ^ (z >> 31);
        }
    }

    uint64_t next() {
        uint64_t result = rotl(s_[1] * 5, 7) * 9;
        uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }

    // Uniform in [0, 1) with 53 random bits.
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    uint64_t s_[4];
};

// Cube root of x > 0 by Newton's method from an exact exponent split, since
// std::cbrt is not correctly rounded everywhere.
double cube_root(double x) {
    int e = 0;
    double m = std::frexp(x, &e);  // x = m * 2^e, m in [0.5, 1), exact
    int r = ((e % 3) + 3) % 3;
    m = std::ldexp(m, r);          // m in [0.5, 4), e - r divisible by 3
    double y = 1.0;
    for (int i = 0; i < 8; ++i) {
        y = (2.0 * y + m / (y * y)) / 3.0;
    }
    return std::ldexp(y, (e - r) / 3);
}

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
    placement.edge = std::max(volume > 0.0 ? cube_root(volume) : 0.0, 2.0 * b);

    Rng rng(c.seed);
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
        const double f = c.moving_fraction;
        SphereState& s = placement.spheres[k];
        s.fixed = std::floor(static_cast<double>(k + 1) * f) == std::floor(static_cast<double>(k) * f);
        if (s.fixed) s.velocity = {0.0, 0.0, 0.0};
    }
    return placement;
}

double centre_limit(double edge, double radius) {
    // Rounding of edge - radius could put centre + radius an ulp past the
    // wall; step hi down until it cannot.
    double hi = edge - radius;
    while (hi + radius > edge) {
        hi = std::nextafter(hi, 0.0);
    }
    return hi;
}

void move_sphere(SphereState& s, double hi, double dt) {
    double lo = s.radius;
    for (int axis = 0; axis < 3; ++axis) {
        double& x = s.centre[axis];
        double& v = s.velocity[axis];
        x += v * dt;
        // Mirror at the wall; the clamp covers a step longer than the free
        // space (tiny cube, huge speed).
        if (x < lo) {
            x = 2.0 * lo - x;
            v = -v;
        } else if (x > hi) {
            x = 2.0 * hi - x;
            v = -v;
        }
        x = std::clamp(x, lo, hi);
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
