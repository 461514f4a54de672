// Two or a few hand-placed spheres: the contact response itself.
#include "sw/apps/bouncing_spheres.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "tests/apps/test_helpers.h"

namespace cdvp {
namespace {

SphereState sphere(double radius, std::array<double, 3> centre, std::array<double, 3> velocity) {
    SphereState s;
    s.radius = radius;
    s.centre = centre;
    s.velocity = velocity;
    return s;
}

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Small dt and a large cube: no wall is reached within one step.
constexpr double kDt = 1e-3;

TEST(BouncingPairs, EqualSpheresHeadOnExchangeVelocities) {
    BouncingSpheres sim({10.0, {sphere(1.0, {4, 5, 5}, {1, 0, 0}),
                                sphere(1.0, {6, 5, 5}, {-1, 0, 0})}},
                        kDt);
    StepStats stats = sim.step({{0, 1}});
    EXPECT_EQ(1u, stats.candidates);
    EXPECT_EQ(1u, stats.contacts);
    const auto& s = sim.spheres();
    EXPECT_EQ((std::array<double, 3>{-1, 0, 0}), s[0].velocity);
    EXPECT_EQ((std::array<double, 3>{1, 0, 0}), s[1].velocity);
    // They move apart after the bounce.
    EXPECT_LT(s[0].centre[0], 4.0);
    EXPECT_GT(s[1].centre[0], 6.0);
}

TEST(BouncingPairs, UnequalMassesConserveMomentumAlongTheNormal) {
    // Radii 1 and 2 (masses 1 and 8), slightly overlapping along (1, 1, 0).
    const double h = std::sqrt(0.5);
    std::array<double, 3> n{h, h, 0.0};
    std::array<double, 3> ca{6, 6, 10};
    std::array<double, 3> cb{ca[0] + 2.9 * h, ca[1] + 2.9 * h, 10};
    BouncingSpheres sim({20.0, {sphere(1.0, ca, {2, 1, 0.5}), sphere(2.0, cb, {-1, 0, 0.3})}},
                        kDt);
    const auto before = sim.spheres();
    const double ma = 1.0, mb = 8.0;
    double ua = dot(before[0].velocity, n);
    double ub = dot(before[1].velocity, n);
    ASSERT_LT(ub - ua, 0.0);  // approaching

    EXPECT_EQ(1u, sim.step({{0, 1}}).contacts);
    const auto& after = sim.spheres();
    double va = dot(after[0].velocity, n);
    double vb = dot(after[1].velocity, n);
    EXPECT_NEAR(ma * ua + mb * ub, ma * va + mb * vb, 1e-12);
    // One-dimensional elastic collision along the normal.
    EXPECT_NEAR(((ma - mb) * ua + 2 * mb * ub) / (ma + mb), va, 1e-12);
    EXPECT_NEAR(((mb - ma) * ub + 2 * ma * ua) / (ma + mb), vb, 1e-12);
    // Tangential velocities are untouched.
    for (int k = 0; k < 2; ++k) {
        for (int axis = 0; axis < 3; ++axis) {
            double tangential_before = before[k].velocity[axis] - dot(before[k].velocity, n) * n[axis];
            double tangential_after = after[k].velocity[axis] - dot(after[k].velocity, n) * n[axis];
            EXPECT_NEAR(tangential_before, tangential_after, 1e-12);
        }
    }
    auto p = sim.momentum();
    EXPECT_NEAR(ma * 2 + mb * -1, p[0], 1e-12);
    EXPECT_NEAR(ma * 1 + mb * 0, p[1], 1e-12);
    EXPECT_NEAR(ma * 0.5 + mb * 0.3, p[2], 1e-12);
}

TEST(BouncingPairs, RestitutionScalesTheSeparationSpeed) {
    BouncingSpheres sim({10.0, {sphere(1.0, {4, 5, 5}, {1, 0, 0}),
                                sphere(1.0, {6, 5, 5}, {-1, 0, 0})}},
                        kDt, 0.5);
    double energy = sim.kinetic_energy();
    sim.step({{0, 1}});
    EXPECT_EQ(-0.5, sim.spheres()[0].velocity[0]);
    EXPECT_EQ(0.5, sim.spheres()[1].velocity[0]);
    EXPECT_NEAR(energy * 0.25, sim.kinetic_energy(), 1e-15);
}

TEST(BouncingPairs, OverlapIsCorrectedWithoutAddingEnergy) {
    // At rest and sunk 0.5 into each other: pushed apart to just touching,
    // the centre of mass stays, nothing starts moving.
    BouncingSpheres sim({20.0, {sphere(1.0, {8, 10, 10}, {0, 0, 0}),
                                sphere(2.0, {10.5, 10, 10}, {0, 0, 0})}},
                        kDt);
    double com = (1 * 8.0 + 8 * 10.5) / 9;
    EXPECT_EQ(1u, sim.step({{0, 1}}).contacts);
    const auto& s = sim.spheres();
    EXPECT_NEAR(3.0, s[1].centre[0] - s[0].centre[0], 1e-12);
    EXPECT_NEAR(com, (1 * s[0].centre[0] + 8 * s[1].centre[0]) / 9, 1e-12);
    EXPECT_EQ(0.0, sim.kinetic_energy());
}

TEST(BouncingPairs, PushedIntoAWallIsNoBounce) {
    // A sits against the wall, moving away from it; B, separating faster,
    // still overlaps it, and the correction pushes A into the wall. A is put
    // back against the wall and keeps its velocity.
    BouncingSpheres sim({10.0, {sphere(1.0, {1.0, 5, 5}, {0.2, 0, 0}),
                                sphere(1.0, {2.5, 5, 5}, {1, 0, 0})}},
                        kDt);
    EXPECT_EQ(1u, sim.step({{0, 1}}).contacts);
    EXPECT_EQ(0.2, sim.spheres()[0].velocity[0]);
    EXPECT_EQ(1.0 + 0.2 * kDt, sim.spheres()[0].centre[0]);
}

TEST(BouncingPairs, SeparatingPairKeepsItsVelocities) {
    BouncingSpheres sim({10.0, {sphere(1.0, {4, 5, 5}, {-1, 0, 0}),
                                sphere(1.0, {5.9, 5, 5}, {1, 0, 0})}},
                        kDt);
    EXPECT_EQ(1u, sim.step({{0, 1}}).contacts);
    EXPECT_EQ(-1.0, sim.spheres()[0].velocity[0]);
    EXPECT_EQ(1.0, sim.spheres()[1].velocity[0]);
}

TEST(BouncingPairs, NonTouchingCandidatesAreIgnored) {
    // Boxes overlap (offset 1.5 < 2 per axis) but the spheres do not touch
    // (distance 1.5 * sqrt(3) > 2), and they approach each other.
    BouncingSpheres sim({10.0, {sphere(1.0, {4, 4, 4}, {1, 1, 1}),
                                sphere(1.0, {5.5, 5.5, 5.5}, {-1, -1, -1}),
                                sphere(1.0, {8, 2, 2}, {0, 0, 0})}},
                        kDt);
    ASSERT_EQ(1u, overlapping_pairs(sim.frame()).size());
    StepStats stats = sim.step({{0, 1}, {1, 2}, {0, 2}});
    EXPECT_EQ(3u, stats.candidates);
    EXPECT_EQ(0u, stats.contacts);
    EXPECT_EQ((std::array<double, 3>{1, 1, 1}), sim.spheres()[0].velocity);
    EXPECT_EQ((std::array<double, 3>{-1, -1, -1}), sim.spheres()[1].velocity);
    EXPECT_EQ(4.0 + kDt, sim.spheres()[0].centre[0]);
}

TEST(BouncingPairs, SwappedAndDuplicatePairsCountOnce) {
    BouncingSpheres sim({10.0, {sphere(1.0, {4, 5, 5}, {1, 0, 0}),
                                sphere(1.0, {6, 5, 5}, {-1, 0, 0})}},
                        kDt);
    StepStats stats = sim.step({{1, 0}, {0, 1}});
    EXPECT_EQ(2u, stats.candidates);
    EXPECT_EQ(1u, stats.contacts);
    EXPECT_EQ(-1.0, sim.spheres()[0].velocity[0]);
}

TEST(BouncingPairs, ZeroAndOneSphere) {
    BouncingSpheres empty({5.0, {}}, kDt);
    EXPECT_TRUE(empty.frame().boxes.empty());
    StepStats stats = empty.step({});
    EXPECT_EQ(0u, stats.candidates);
    EXPECT_EQ(0u, stats.contacts);
    EXPECT_EQ(1u, empty.frame().number);
    EXPECT_EQ(0.0, empty.kinetic_energy());
    EXPECT_THROW(empty.step({{0, 1}}), std::out_of_range);

    BouncingSpheresConfig config;
    config.objects = 1;
    config.volume_fraction = 0.9;  // the cube is then as small as allowed
    config.max_speed = 100.0;
    BouncingSpheres one(config);
    double energy = one.kinetic_energy();
    for (int k = 0; k < 200; ++k) {
        ASSERT_EQ(0u, one.step({}).contacts);
        Frame frame = one.frame();
        ASSERT_EQ(1u, frame.boxes.size());
        for (int axis = 0; axis < 3; ++axis) {
            ASSERT_LE(0.0, frame.boxes[0].min[axis]);
            ASSERT_LE(frame.boxes[0].max[axis], one.edge());
        }
    }
    EXPECT_EQ(energy, one.kinetic_energy());
    EXPECT_THROW(one.step({{0, 0}}), std::invalid_argument);
    EXPECT_THROW(one.step({{0, 1}}), std::out_of_range);
}

TEST(BouncingPairs, RejectsBadInput) {
    BouncingSpheresConfig config;
    config.restitution = 1.5;
    EXPECT_THROW(BouncingSpheres{config}, InputError);
    config.restitution = std::nan("");
    EXPECT_THROW(BouncingSpheres{config}, InputError);
    config = BouncingSpheresConfig{};
    config.radius_min = 0.0;  // massless spheres
    EXPECT_THROW(BouncingSpheres{config}, InputError);
    config = BouncingSpheresConfig{};
    config.volume_fraction = 1.0;  // checked by the shared placement
    EXPECT_THROW(BouncingSpheres{config}, InputError);
    EXPECT_NO_THROW(BouncingSpheres{BouncingSpheresConfig{}});

    EXPECT_THROW(BouncingSpheres({10.0, {sphere(1.0, {0.5, 5, 5}, {0, 0, 0})}}, kDt),
                 InputError);  // pokes through a wall
    EXPECT_THROW(BouncingSpheres({10.0, {sphere(1.0, {5, 5, 5}, {0, INFINITY, 0})}}, kDt),
                 InputError);
    EXPECT_THROW(BouncingSpheres({10.0, {}}, -1.0), InputError);
}

}  // namespace
}  // namespace cdvp
