// The paper's application: spheres bouncing in a closed box, off the walls
// and off each other. The broad phase is not part of it: every step takes
// the candidate pairs from the caller (the virtual board or a software
// broad phase), so the same application runs on either.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "models/common/aabb.h"
#include "sw/scene/scene.h"
#include "sw/scene/spheres.h"

namespace cdvp {

// The SpheresConfig fields keep their meaning and defaults (same seed, same
// start as SpheresScene), except that radius_min must be > 0: a sphere's
// mass is proportional to radius^3.
struct BouncingSpheresConfig : SpheresConfig {
    double restitution = 1.0;  // between spheres, in [0, 1]; 1 = elastic. Walls are elastic.
};

struct StepStats {
    std::size_t candidates = 0;  // broad-phase pairs passed in
    std::size_t contacts = 0;    // distinct sphere pairs touching
};

class BouncingSpheres {
public:
    // Places the spheres as SpheresScene does. InputError on a bad config.
    explicit BouncingSpheres(const BouncingSpheresConfig& config);

    // A hand-built start (tests, traces of special cases): every sphere
    // needs radius > 0, centre within [radius, edge - radius] per axis and a
    // finite velocity. InputError otherwise.
    BouncingSpheres(SpheresPlacement start, double dt, double restitution = 1.0);

    // The current state's bounding boxes: number = frames stepped so far,
    // ids 0..N-1, box = centre +- radius.
    Frame frame() const;

    // One step given the broad phase's candidate pairs for frame(): indices
    // in any order (first > second is swapped; duplicates count once), may
    // include non-touching pairs, must include every touching pair. Narrow
    // phase (distance <= r1 + r2), elastic response along the contact normal
    // for approaching pairs, positional correction so spheres do not sink
    // into each other, wall bounces, integration by dt. Pairs are processed
    // in sorted (first, second) order, so the result does not depend on the
    // candidates' order. Throws std::out_of_range for an index >= N and
    // std::invalid_argument for a pair (i, i).
    StepStats step(const PairList& candidates);

    // Mass = radius^3 (density 3 / (4 pi)).
    double kinetic_energy() const;
    std::array<double, 3> momentum() const;

    double edge() const { return edge_; }  // the cube is [0, edge]^3
    const std::vector<SphereState>& spheres() const { return spheres_; }

private:
    struct Contact {
        uint32_t a;
        uint32_t b;
        std::array<double, 3> normal;  // unit, from a towards b
        double depth;                  // r_a + r_b - distance, >= 0
    };

    PairList sorted_pairs(const PairList& candidates) const;
    void resolve(const Contact& contact);

    double edge_ = 0.0;
    double dt_ = 0.0;
    double restitution_ = 1.0;
    uint64_t number_ = 0;
    std::vector<SphereState> spheres_;
    std::vector<double> hi_;  // centre_limit(edge_, radius) per sphere
};

}  // namespace cdvp
