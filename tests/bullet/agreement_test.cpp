// The board's world against btAxisSweep3's and btDbvtBroadphase's worlds. They
// find the same overlaps but hand them to the cache in other orders, so the
// solver visits contacts in another order and chaotic scenes drift apart:
// only aggregates can agree. See docs/bullet.md for the tolerances' reasons.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sw/bullet/scenes.h"
#include "tests/bullet/bullet_test_support.h"

namespace cdvp {
namespace {

struct RunSummary {
    double mean_contacts = 0;  // contact points per frame, over the run
    double final_energy = 0;   // kinetic energy after the last frame
    std::size_t final_contacts = 0;
    std::size_t awake = 0;
};

RunSummary run(const SceneSpec& spec, BroadphaseKind kind, int frames, BoardLink* link) {
    auto world = make_scene_world(spec, kind, link);
    RunSummary summary;
    for (int frame = 0; frame < frames; ++frame) {
        world->step();
        summary.mean_contacts += static_cast<double>(world->contact_points()) / frames;
    }
    summary.final_energy = world->kinetic_energy();
    summary.final_contacts = world->contact_points();
    summary.awake = world->awake_bodies();
    return summary;
}

struct Tolerance {
    double contacts;  // relative, on the mean contact points per frame
    double energy;    // relative, on the final kinetic energy
    double energy_floor;  // absolute, in J: below it energies count as equal (a scene at rest)
};

void expect_agreement(const SceneSpec& spec, int frames, Tolerance tolerance) {
    PlatformConfig config;
    config.fidelity = Fidelity::kFast;
    LazyVirtualBoard link(config, scene_layout(spec).proxies);
    const RunSummary board = run(spec, BroadphaseKind::kBoard, frames, &link);
    EXPECT_GT(board.mean_contacts, 0.0);
    for (BroadphaseKind kind : {BroadphaseKind::kSimple, BroadphaseKind::kSap, BroadphaseKind::kDbvt}) {
        const RunSummary other = run(spec, kind, frames, nullptr);
        std::printf("%s on %s: contacts %.1f against %.1f, energy %.4g against %.4g\n", spec.name.c_str(),
                    to_string(kind), board.mean_contacts, other.mean_contacts, board.final_energy, other.final_energy);
        EXPECT_NEAR(board.mean_contacts, other.mean_contacts, tolerance.contacts * other.mean_contacts)
            << spec.name << " against " << to_string(kind);
        EXPECT_NEAR(board.final_energy, other.final_energy,
                    std::max(tolerance.energy * other.final_energy, tolerance.energy_floor))
            << spec.name << " against " << to_string(kind);
    }
}

TEST(BroadphaseAgreement, Pyramid) { expect_agreement({"pyramid", 55, 1}, 120, {0.20, 0.25, 1.0}); }
TEST(BroadphaseAgreement, Boxes) { expect_agreement({"boxes", 400, 2}, 90, {0.05, 0.25, 1.0}); }
TEST(BroadphaseAgreement, Mixed) { expect_agreement({"mixed", 200, 3}, 90, {0.20, 0.25, 1.0}); }
TEST(BroadphaseAgreement, Spheres) { expect_agreement({"bullet-spheres", 150, 5}, 120, {0.10, 0.05, 0.0}); }

// A stack settles into the same rest whatever the order: the same contacts,
// no motion, every body asleep.
TEST(BroadphaseAgreement, StacksSettleAndSleepTheSameOnEveryBroadphase) {
    const SceneSpec spec{"stack", 30, 4};
    PlatformConfig config;
    config.fidelity = Fidelity::kFast;
    LazyVirtualBoard link(config, scene_layout(spec).proxies);
    const RunSummary board = run(spec, BroadphaseKind::kBoard, 240, &link);
    EXPECT_EQ(board.awake, 0u) << "the stacks should be asleep after 4 s";
    for (BroadphaseKind kind : {BroadphaseKind::kSimple, BroadphaseKind::kSap, BroadphaseKind::kDbvt}) {
        const RunSummary other = run(spec, kind, 240, nullptr);
        EXPECT_EQ(board.final_contacts, other.final_contacts) << to_string(kind);
        EXPECT_EQ(other.awake, 0u) << to_string(kind);
        EXPECT_LT(board.final_energy, 1e-6);
    }
}

}  // namespace
}  // namespace cdvp
