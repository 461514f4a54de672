// A deterministic synthetic scene: spheres flying through a closed cube and
// bouncing off its walls (they pass through each other; sw/apps has spheres
// that bounce off each other too). Each frame gives every sphere's bounding box.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sw/scene/scene.h"
#include "sw/scene/scene_random.h"  // centre_limit

namespace cdvp {

// Lengths in scene units, times in seconds, speeds in scene units/second.
struct SpheresConfig {
    std::size_t objects = 500;
    uint64_t seed = 1;
    double radius_min = 0.5;        // radii uniform in [radius_min, radius_max]
    double radius_max = 1.0;
    double volume_fraction = 0.15;  // sphere volume / cube volume, in (0, 1)
    double max_speed = 4.0;         // velocities uniform in the ball of this radius
    double dt = 1.0 / 60.0;         // time between frames
    // The share of spheres that move, spread evenly over the indices; the
    // rest are static bodies (no velocity, and, in the bouncing
    // application, infinite mass), as a physics scene's level geometry is.
    double moving_fraction = 1.0;
};

// The pieces below are shared with the bouncing-spheres application
// (sw/apps), so both start from the same state for the same config.

// One sphere: centre and velocity per axis.
struct SphereState {
    double radius = 0.0;
    std::array<double, 3> centre{};
    std::array<double, 3> velocity{};
    bool fixed = false;  // a static body: never moves (SpheresConfig::moving_fraction)
};

// The cube's edge and the spheres placed in it, all inside [0, edge]^3.
struct SpheresPlacement {
    double edge = 0.0;
    std::vector<SphereState> spheres;
};

// Validates config (InputError) and places config.objects spheres: radii,
// centres and velocities drawn from config.seed; edge as SpheresScene::edge().
SpheresPlacement place_spheres(const SpheresConfig& config);

// Moves s by dt, mirroring it at the walls: each centre coordinate stays in
// [radius, hi] with hi = centre_limit(edge, radius).
void move_sphere(SphereState& s, double hi, double dt);

// Frame `number`: ids 0..N-1, boxes centre +- radius.
Frame spheres_frame(uint64_t number, const std::vector<SphereState>& spheres);

class SpheresScene {
public:
    // Places the spheres. The cube's edge is chosen so the spheres' expected
    // total volume is volume_fraction of the cube (so the overlap density
    // stays about the same as objects grows), but never less than
    // 2 * radius_max. Throws InputError for a config out of range.
    explicit SpheresScene(const SpheresConfig& config);

    // Frame k (k = 0, 1, ...): number k, ids 0..N-1, boxes centre +- radius.
    // Frame 0 is the initial state; each later call first advances by dt.
    Frame next();

    // The cube is [0, edge()]^3; every box stays inside it.
    double edge() const { return edge_; }

private:
    void advance();

    SpheresConfig config_;
    double edge_ = 0.0;
    uint64_t next_number_ = 0;
    std::vector<SphereState> spheres_;
    std::vector<double> hi_;  // centre_limit(edge_, radius) per sphere
};

}  // namespace cdvp
