// The board broad phase inside btDiscreteDynamicsWorld: its pair cache against
// brute force every frame, bit for bit against btSimpleBroadphase, under proxy
// churn and collision filters. Each test runs in its own process (one board
// per process), on the fast engine unless it says otherwise.
#include <gtest/gtest.h>

#include <random>

#include "sw/bullet/scenes.h"
#include "tests/bullet/bullet_test_support.h"

namespace cdvp {
namespace {

using testing::cached_pairs;
using testing::exact_pairs;
using testing::same_state;

PlatformConfig platform(Fidelity fidelity = Fidelity::kFast) {
    PlatformConfig config;
    config.board.m = 8;
    config.fidelity = fidelity;
    return config;
}

BoardBroadphase& board_of(BulletWorld& world) { return dynamic_cast<BoardBroadphase&>(world.broadphase()); }

// After a step the proxies still hold the AABBs the board saw (only the next
// step's updateAabbs moves them), so brute force over them is that frame's truth.
void expect_exact_pairs(BulletWorld& world, const std::string& where) {
    const BoardBroadphase& board = board_of(world);
    EXPECT_EQ(board.last_frame().board_pairs, exact_pairs(world.world(), false).size()) << where;
    EXPECT_EQ(cached_pairs(*board.getOverlappingPairCache()), exact_pairs(world.world())) << where;
}

void run_exact(const SceneSpec& spec, int frames, Fidelity fidelity) {
    LazyVirtualBoard link(platform(fidelity), scene_layout(spec).proxies);
    auto world = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    std::size_t changes = 0;
    for (int frame = 0; frame < frames; ++frame) {
        world->step();
        ASSERT_EQ(board_of(*world).last_frame().proxies, scene_layout(spec).proxies);
        expect_exact_pairs(*world, spec.name + " frame " + std::to_string(frame));
        changes += board_of(*world).last_frame().added + board_of(*world).last_frame().removed;
    }
    EXPECT_GT(changes, 0u) << "the pair set should change during the run";
}

TEST(BoardBroadphase, PyramidPairsAreExactEveryFrame) { run_exact({"pyramid", 55, 1}, 60, Fidelity::kFast); }
TEST(BoardBroadphase, BoxesPairsAreExactEveryFrame) { run_exact({"boxes", 400, 2}, 40, Fidelity::kFast); }
TEST(BoardBroadphase, MixedPairsAreExactEveryFrame) { run_exact({"mixed", 200, 3}, 60, Fidelity::kFast); }
TEST(BoardBroadphase, StackPairsAreExactEveryFrame) { run_exact({"stack", 30, 4}, 40, Fidelity::kFast); }
TEST(BoardBroadphase, SpheresPairsAreExactEveryFrame) { run_exact({"bullet-spheres", 150, 5}, 60, Fidelity::kFast); }
TEST(BoardBroadphase, ClockedEnginePairsAreExactEveryFrame) { run_exact({"mixed", 60, 6}, 20, Fidelity::kCycle); }

// The board's cache sees btSimpleBroadphase's add and remove calls in the same
// order with the same unique ids, so the dispatcher, the manifolds and the
// solver see the same sequence and every float comes out the same.
void run_bit_identical(const SceneSpec& spec, int frames) {
    LazyVirtualBoard link(platform(), scene_layout(spec).proxies);
    auto board = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    auto simple = make_scene_world(spec, BroadphaseKind::kSimple);
    for (int frame = 0; frame < frames; ++frame) {
        board->step();
        simple->step();
        ASSERT_TRUE(same_state(*board, *simple)) << spec.name << " frame " << frame;
        ASSERT_EQ(board->contact_points(), simple->contact_points()) << spec.name << " frame " << frame;
    }
    EXPECT_GT(board->contact_points(), 0u) << "the scene should be in contact by its end";
}

TEST(BoardBroadphase, PyramidIsBitIdenticalToSimpleBroadphase) { run_bit_identical({"pyramid", 55, 1}, 90); }
TEST(BoardBroadphase, BoxesAreBitIdenticalToSimpleBroadphase) { run_bit_identical({"boxes", 300, 2}, 60); }
TEST(BoardBroadphase, MixedIsBitIdenticalToSimpleBroadphase) { run_bit_identical({"mixed", 150, 3}, 60); }
TEST(BoardBroadphase, StackIsBitIdenticalToSimpleBroadphase) { run_bit_identical({"stack", 30, 4}, 60); }
TEST(BoardBroadphase, SpheresAreBitIdenticalToSimpleBroadphase) { run_bit_identical({"bullet-spheres", 150, 5}, 60); }

// What makes the identity above worth testing: Bullet's other broad phases
// find the same overlaps but add them in another order, and the worlds part.
TEST(BoardBroadphase, PairOrderMattersDbvtWorldsPartFromSimpleOnes) {
    const SceneSpec spec{"pyramid", 55, 1};
    auto dbvt = make_scene_world(spec, BroadphaseKind::kDbvt);
    auto simple = make_scene_world(spec, BroadphaseKind::kSimple);
    bool parted = false;
    for (int frame = 0; frame < 90 && !parted; ++frame) {
        dbvt->step();
        simple->step();
        parted = !same_state(*dbvt, *simple);
    }
    EXPECT_TRUE(parted);
}

// Bodies removed and added between steps, the same in both worlds: freed
// slots are reused last-freed-first as btSimpleBroadphase reuses handles, no
// pair of a destroyed proxy survives, and the worlds stay bit-identical.
TEST(BoardBroadphase, ProxyChurnMidSimulationKeepsPairsExactAndWorldsIdentical) {
    const SceneSpec spec{"mixed", 120, 7};
    LazyVirtualBoard link(platform(), scene_layout(spec).proxies + 40);
    auto board = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    auto simple = make_scene_world(spec, BroadphaseKind::kSimple);
    std::mt19937 rng(11);
    btCollisionShape* shapes[2] = {board->keep_shape(std::make_unique<btSphereShape>(0.3f)),
                                   simple->keep_shape(std::make_unique<btSphereShape>(0.3f))};
    std::size_t destroyed = 0, created = 0;
    for (int frame = 0; frame < 60; ++frame) {
        if (frame % 5 == 2) {
            const auto victim = std::uniform_int_distribution<std::size_t>(1, board->bodies().size() - 1)(rng);
            board->remove_body(board->bodies()[victim]);
            simple->remove_body(simple->bodies()[victim]);
            ++destroyed;
        }
        if (frame % 3 == 1) {
            const btVector3 at(std::uniform_real_distribution<float>(-4, 4)(rng), 6, 0);
            board->add_body(shapes[0], 1, btTransform(btQuaternion::getIdentity(), at));
            simple->add_body(shapes[1], 1, btTransform(btQuaternion::getIdentity(), at));
            ++created;
        }
        board->step();
        simple->step();
        expect_exact_pairs(*board, "frame " + std::to_string(frame));
        EXPECT_EQ(board_of(*board).proxy_count(), board->world().getNumCollisionObjects());
        ASSERT_TRUE(same_state(*board, *simple)) << "frame " << frame;
    }
    EXPECT_EQ(destroyed, 12u);
    EXPECT_EQ(created, 20u);
}

// Groups and masks: debris collides with the ground only, sensors with
// nothing but debris; the cache holds exactly the pairs the masks allow.
TEST(BoardBroadphase, CollisionFilterGroupsAndMasksAreHonoured) {
    const SceneSpec spec{"stack", 20, 8};
    LazyVirtualBoard link(platform(), scene_layout(spec).proxies + 30);
    auto world = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    btCollisionShape* ball = world->keep_shape(std::make_unique<btSphereShape>(0.4f));
    const int debris = btBroadphaseProxy::DebrisFilter, sensor = btBroadphaseProxy::SensorTrigger;
    for (int k = 0; k < 15; ++k) {
        const btTransform at(btQuaternion::getIdentity(), btVector3(0.2f * k, 0.5f + 0.3f * k, 0.1f));
        world->add_body(ball, 1, at, debris, btBroadphaseProxy::StaticFilter | sensor);
        world->add_body(ball, 0, at, sensor, debris);
    }
    std::size_t debris_sensor = 0;
    for (int frame = 0; frame < 30; ++frame) {
        world->step();
        expect_exact_pairs(*world, "frame " + std::to_string(frame));
        const btBroadphasePairArray& pairs = world->broadphase().getOverlappingPairCache()->getOverlappingPairArray();
        for (int k = 0; k < pairs.size(); ++k) {
            const int groups = pairs[k].m_pProxy0->m_collisionFilterGroup | pairs[k].m_pProxy1->m_collisionFilterGroup;
            EXPECT_NE(groups, debris) << "debris never meets debris";
            EXPECT_NE(groups, sensor) << "sensors never meet sensors";
            if (groups == (debris | sensor)) ++debris_sensor;
        }
    }
    EXPECT_GT(debris_sensor, 0u) << "debris and sensors overlap in this scene";
    EXPECT_LT(exact_pairs(world->world()).size(), exact_pairs(world->world(), false).size())
        << "the masks should reject some overlaps";
}

// A user's overlap filter callback on the cache decides instead of the masks.
struct EvenUidsOnly : btOverlapFilterCallback {
    bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override {
        return a->getUid() % 2 == 0 && b->getUid() % 2 == 0;
    }
};

TEST(BoardBroadphase, TheCachesOverlapFilterCallbackDecides) {
    const SceneSpec spec{"mixed", 80, 9};
    LazyVirtualBoard link(platform(), scene_layout(spec).proxies);
    auto world = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    EvenUidsOnly filter;
    world->broadphase().getOverlappingPairCache()->setOverlapFilterCallback(&filter);
    for (int frame = 0; frame < 40; ++frame) {
        world->step();
        expect_exact_pairs(*world, "frame " + std::to_string(frame));
        for (const auto& [a, b] : cached_pairs(*world->broadphase().getOverlappingPairCache())) {
            ASSERT_TRUE(a % 2 == 0 && b % 2 == 0);
        }
    }
    EXPECT_FALSE(cached_pairs(*world->broadphase().getOverlappingPairCache()).empty());
}

}  // namespace
}  // namespace cdvp
