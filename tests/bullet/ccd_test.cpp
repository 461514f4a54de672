// Continuous collision detection on the board's broad phase. btDiscreteDynamicsWorld
// sweeps each fast CCD body (convexSweepTest: btBroadphaseInterface::rayTest
// with the swept sphere's box) before moving it, so the broad phase's ray
// query decides whether a wall is seen. Worlds are stepped on the board (fast
// engine) beside btSimpleBroadphase and btDbvtBroadphase and compared bit for
// bit every frame. Each test runs in its own process (one board per process).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "sw/bullet/scenes.h"
#include "tests/bullet/bullet_test_support.h"

namespace cdvp {
namespace {

using testing::same_contacts;
using testing::same_state;

constexpr btScalar kRadius = 0.05f;       // the projectiles' radius
constexpr btScalar kWallX = 3;            // walls at x = +-3
constexpr btScalar kWallHalfThickness = 0.02f;
constexpr int kLanes = 36;                // 6 x 6 lanes, 2 apart: projectiles never meet
// Metres per second; per 1/60 s step: 0.3, 0.45, 0.7, 0.9 (shorter than a
// unit, so the sweeps' m_lambda_max is below 1), 1.5 and 2.5.
constexpr btScalar kSpeeds[] = {18, 27, 42, 54, 90, 150};

// A shooting gallery: small fast spheres between two thin static walls. Each
// sphere moves more than its diameter plus a wall's thickness a step, so
// without CCD it passes through; with it, it bounces between the walls. The
// spheres touch only the walls (static: they merge no islands), so the order
// in which a broad phase hands over pairs does not matter, and a world on
// btDbvtBroadphase can be bit-identical too.
void build_gallery(BulletWorld& world, bool ccd, uint64_t seed) {
    world.world().setGravity(btVector3(0, 0, 0));
    world.world().getDispatchInfo().m_deterministicOverlappingPairs = true;
    btCollisionShape* wall =
        world.keep_shape(std::make_unique<btBoxShape>(btVector3(kWallHalfThickness, 8, 8)));
    for (btScalar x : {-kWallX, kWallX}) {
        world.add_body(wall, 0, btTransform(btQuaternion::getIdentity(), btVector3(x, 0, 0)))->setRestitution(1);
    }
    btCollisionShape* sphere = world.keep_shape(std::make_unique<btSphereShape>(kRadius));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> start(-2.5f, 2.5f), drift(-0.3f, 0.3f);
    for (int lane = 0; lane < kLanes; ++lane) {
        const btVector3 at(start(rng), btScalar(lane / 6) * 2 - 5, btScalar(lane % 6) * 2 - 5);
        btRigidBody* body = world.add_body(sphere, 0.1f, btTransform(btQuaternion::getIdentity(), at));
        const btScalar speed = kSpeeds[lane % 6] * (lane % 4 < 2 ? 1 : -1);
        body->setLinearVelocity(btVector3(speed, drift(rng), drift(rng)));
        body->setRestitution(0.6f);
        if (ccd) {
            body->setCcdMotionThreshold(kRadius);
            body->setCcdSweptSphereRadius(0.8f * kRadius);
        }
    }
}

// Projectiles that left the space between the walls.
int escaped(const BulletWorld& world) {
    int out = 0;
    for (const btRigidBody* body : world.bodies()) {
        if (body->getInvMass() != 0 && std::abs(body->getCenterOfMassPosition().x()) > kWallX) ++out;
    }
    return out;
}

std::unique_ptr<BulletWorld> gallery(BroadphaseKind kind, bool ccd, BoardLink* link = nullptr) {
    auto world = std::make_unique<BulletWorld>(
        make_broadphase(kind, btVector3(-20, -20, -20), btVector3(20, 20, 20), kLanes + 2, link));
    build_gallery(*world, ccd, 7);
    return world;
}

PlatformConfig fast_board() {
    PlatformConfig config;
    config.board.m = 8;
    config.fidelity = Fidelity::kFast;
    return config;
}

constexpr int kFrames = 120;

// What makes the test below worth running: without CCD the projectiles pass
// through the walls; with it, on Bullet's own broad phase, none does.
TEST(BoardCcd, TheGallerysProjectilesTunnelWithoutCcdAndStayInWithIt) {
    auto plain = gallery(BroadphaseKind::kSimple, false);
    auto swept = gallery(BroadphaseKind::kSimple, true);
    for (int frame = 0; frame < kFrames; ++frame) {
        plain->step();
        swept->step();
    }
    std::printf("after %d frames: %d of %d projectiles through the walls without CCD, %d with it\n", kFrames,
                escaped(*plain), kLanes, escaped(*swept));
    EXPECT_GE(escaped(*plain), kLanes * 3 / 4);
    EXPECT_EQ(escaped(*swept), 0);
}

// Every frame, every body and every contact point bit for bit: the board's
// sweeps see the walls exactly where Bullet's broad phases let the sweeps see them.
TEST(BoardCcd, FastSmallBodiesAreBitIdenticalToSimpleAndDbvtBroadphases) {
    LazyVirtualBoard link(fast_board(), kLanes + 2);
    auto board = gallery(BroadphaseKind::kBoard, true, &link);
    auto simple = gallery(BroadphaseKind::kSimple, true);
    auto dbvt = gallery(BroadphaseKind::kDbvt, true);
    int contact_frames = 0;
    for (int frame = 0; frame < kFrames; ++frame) {
        board->step();
        simple->step();
        dbvt->step();
        ASSERT_TRUE(same_state(*board, *simple)) << "frame " << frame << " against btSimpleBroadphase";
        ASSERT_TRUE(same_contacts(board->world(), simple->world())) << "frame " << frame << " against btSimpleBroadphase";
        ASSERT_TRUE(same_state(*board, *dbvt)) << "frame " << frame << " against btDbvtBroadphase";
        ASSERT_TRUE(same_contacts(board->world(), dbvt->world())) << "frame " << frame << " against btDbvtBroadphase";
        contact_frames += board->contact_points() > 0 ? 1 : 0;
    }
    std::printf("%d frames bit-identical to both, %d of them with contact points; %d projectiles through the walls\n",
                kFrames, contact_frames, escaped(*board));
    EXPECT_EQ(escaped(*board), 0);
    EXPECT_GT(contact_frames, kFrames / 4) << "the projectiles should keep hitting the walls";
}

// CCD on every dynamic body of a collapsing scene (the pyramid's 25 m/s ball,
// the mixed pile): sweeps among many moving bodies.
void enable_ccd(BulletWorld& world) {
    for (btRigidBody* body : world.bodies()) {
        if (body->getInvMass() == 0) continue;
        body->setCcdMotionThreshold(0.05f);
        body->setCcdSweptSphereRadius(0.2f);
    }
}

std::unique_ptr<BulletWorld> ccd_scene(const SceneSpec& spec, BroadphaseKind kind, bool deterministic,
                                       BoardLink* link = nullptr) {
    auto world = make_scene_world(spec, kind, link);
    world->world().getDispatchInfo().m_deterministicOverlappingPairs = deterministic;
    enable_ccd(*world);
    return world;
}

// Against btSimpleBroadphase in Bullet's default mode; against btDbvtBroadphase
// too when Bullet sorts pairs and manifolds by unique id
// (m_deterministicOverlappingPairs), as then its pair order does not matter.
void run_ccd_scene(const SceneSpec& spec, int frames, bool deterministic) {
    LazyVirtualBoard link(fast_board(), scene_layout(spec).proxies);
    auto board = ccd_scene(spec, BroadphaseKind::kBoard, deterministic, &link);
    auto simple = ccd_scene(spec, BroadphaseKind::kSimple, deterministic);
    auto dbvt = deterministic ? ccd_scene(spec, BroadphaseKind::kDbvt, true) : nullptr;
    for (int frame = 0; frame < frames; ++frame) {
        board->step();
        simple->step();
        ASSERT_TRUE(same_state(*board, *simple)) << spec.name << " frame " << frame;
        ASSERT_TRUE(same_contacts(board->world(), simple->world())) << spec.name << " frame " << frame;
        if (!dbvt) continue;
        dbvt->step();
        ASSERT_TRUE(same_state(*board, *dbvt)) << spec.name << " frame " << frame << " against btDbvtBroadphase";
        ASSERT_TRUE(same_contacts(board->world(), dbvt->world())) << spec.name << " frame " << frame;
    }
    EXPECT_GT(board->contact_points(), 0u);
}

TEST(BoardCcd, PyramidWithCcdIsBitIdenticalToSimpleAndDbvtBroadphases) { run_ccd_scene({"pyramid", 55, 1}, 90, true); }
TEST(BoardCcd, PyramidWithCcdIsBitIdenticalToSimpleBroadphaseInBulletsDefaultMode) {
    run_ccd_scene({"pyramid", 55, 1}, 90, false);
}
TEST(BoardCcd, MixedPileWithCcdIsBitIdenticalToSimpleBroadphase) { run_ccd_scene({"mixed", 150, 3}, 60, false); }

// Why the mixed pile is held to btSimpleBroadphase alone. With the pairs
// sorted, btDbvtBroadphase's world stays bit-identical without CCD; with it, a
// body pair can hold two manifolds in a step (its contact manifold and the
// CCD's predictive one), Bullet's sort by island and unique ids leaves them in
// the order of the dispatcher's manifold array, and that order follows the
// broad phase's pair history (btDbvt's grown leaves pair bodies a little apart):
// the solver then meets the two in another order and the worlds part.
TEST(BoardCcd, DbvtWorldsPartWhereCcdGivesABodyPairTwoManifolds) {
    const SceneSpec spec{"mixed", 150, 3};
    const auto parts_within = [&](int frames, bool ccd) {
        auto simple = ccd_scene(spec, BroadphaseKind::kSimple, true);
        auto dbvt = ccd_scene(spec, BroadphaseKind::kDbvt, true);
        if (!ccd) {
            for (BulletWorld* world : {simple.get(), dbvt.get()}) {
                for (btRigidBody* body : world->bodies()) body->setCcdMotionThreshold(0);
            }
        }
        for (int frame = 0; frame < frames; ++frame) {
            simple->step();
            dbvt->step();
            if (!same_state(*simple, *dbvt)) return true;
        }
        return false;
    };
    EXPECT_FALSE(parts_within(60, false));
    EXPECT_TRUE(parts_within(60, true));
}

}  // namespace
}  // namespace cdvp
