// Whole scenes: conservation, containment and determinism over many steps.
#include "sw/apps/bouncing_spheres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/apps/test_helpers.h"

namespace cdvp {
namespace {

BouncingSpheresConfig scene(std::size_t objects) {
    BouncingSpheresConfig config;
    config.objects = objects;
    return config;
}

TEST(BouncingScene, StartsWhereSpheresSceneStarts) {
    BouncingSpheresConfig config = scene(100);
    BouncingSpheres sim(config);
    SpheresScene plain(config);
    EXPECT_EQ(plain.edge(), sim.edge());
    EXPECT_TRUE(same_frame(plain.next(), sim.frame()));
}

TEST(BouncingScene, FramesNumberedWithIdsAndSphereBoxes) {
    BouncingSpheres sim(scene(20));
    for (uint64_t k = 0; k < 5; ++k) {
        Frame frame = sim.frame();
        ASSERT_EQ(k, frame.number);
        ASSERT_EQ(20u, frame.ids.size());
        for (std::size_t i = 0; i < 20; ++i) {
            const SphereState& s = sim.spheres()[i];
            ASSERT_EQ(i, frame.ids[i]);
            ASSERT_EQ(s.centre[1] - s.radius, frame.boxes[i].min[1]);
            ASSERT_EQ(s.centre[2] + s.radius, frame.boxes[i].max[2]);
        }
        sim.step(overlapping_pairs(frame));
    }
}

TEST(BouncingScene, ElasticSceneKeepsItsEnergy) {
    BouncingSpheres sim(scene(200));
    const double energy = sim.kinetic_energy();
    ASSERT_GT(energy, 0.0);
    std::size_t contacts = 0;
    for (int k = 0; k < 500; ++k) {
        contacts += sim.step(overlapping_pairs(sim.frame())).contacts;
        ASSERT_NEAR(energy, sim.kinetic_energy(), 1e-9 * energy) << "step " << k;
    }
    EXPECT_GT(contacts, 500u);  // the spheres really did collide
}

TEST(BouncingScene, InelasticSceneLosesEnergy) {
    BouncingSpheresConfig config = scene(200);
    config.restitution = 0.5;
    BouncingSpheres sim(config);
    const double energy = sim.kinetic_energy();
    double previous = energy;
    for (int k = 0; k < 300; ++k) {
        sim.step(overlapping_pairs(sim.frame()));
        ASSERT_LE(sim.kinetic_energy(), previous * (1 + 1e-12)) << "step " << k;
        previous = sim.kinetic_energy();
    }
    EXPECT_LT(previous, 0.8 * energy);
}

TEST(BouncingScene, SpheresNeverLeaveTheCube) {
    // Fast and crowded: many wall bounces and corrections near the walls.
    BouncingSpheresConfig config = scene(300);
    config.max_speed = 40.0;
    config.volume_fraction = 0.3;
    BouncingSpheres sim(config);
    for (int k = 0; k <= 500; ++k) {
        Frame frame = sim.frame();
        for (const Box& b : frame.boxes) {
            for (int axis = 0; axis < 3; ++axis) {
                ASSERT_LE(0.0, b.min[axis]) << "frame " << k;
                ASSERT_LE(b.max[axis], sim.edge()) << "frame " << k;
            }
        }
        sim.step(overlapping_pairs(frame));
    }
}

TEST(BouncingScene, SameSeedGivesIdenticalFrames) {
    BouncingSpheres a(scene(200));
    BouncingSpheres b(scene(200));
    BouncingSpheresConfig other = scene(200);
    other.seed = 2;
    BouncingSpheres c(other);
    EXPECT_FALSE(same_frame(a.frame(), c.frame()));
    for (int k = 0; k < 100; ++k) {
        ASSERT_TRUE(same_frame(a.frame(), b.frame())) << "frame " << k;
        a.step(overlapping_pairs(a.frame()));
        b.step(overlapping_pairs(b.frame()));
    }
}

TEST(BouncingScene, CandidateOrderDoesNotMatter) {
    // Crowded, so spheres touch several others at once and the order of
    // the sequential responses matters.
    BouncingSpheresConfig config = scene(200);
    config.volume_fraction = 0.3;
    BouncingSpheres sorted(config);
    BouncingSpheres shuffled(config);
    std::mt19937 rng(7);
    for (int k = 0; k < 100; ++k) {
        PairList pairs = overlapping_pairs(sorted.frame());
        PairList mixed = pairs;
        std::shuffle(mixed.begin(), mixed.end(), rng);
        sorted.step(pairs);
        shuffled.step(mixed);
        ASSERT_TRUE(same_frame(sorted.frame(), shuffled.frame())) << "frame " << k;
    }
}

TEST(BouncingScene, ExtraCandidatesChangeNothing) {
    // A broad phase that rejects nothing gives the same frames and contacts
    // as the exact AABB test.
    BouncingSpheres exact(scene(60));
    BouncingSpheres everything(scene(60));
    const PairList all = all_pairs(60);
    for (int k = 0; k < 200; ++k) {
        StepStats a = exact.step(overlapping_pairs(exact.frame()));
        StepStats b = everything.step(all);
        ASSERT_EQ(a.contacts, b.contacts) << "step " << k;
        ASSERT_EQ(all.size(), b.candidates);
        ASSERT_TRUE(same_frame(exact.frame(), everything.frame())) << "frame " << k;
    }
}

}  // namespace
}  // namespace cdvp
