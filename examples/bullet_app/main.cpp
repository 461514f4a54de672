// A few dozen boxes and spheres falling on a ground plane, in a plain
// btDiscreteDynamicsWorld whose broad phase is cdvp's board (the paper's
// ADM-XRC-II preset), stepped beside the same world on btSimpleBroadphase.
// Beside the column, a small sphere with continuous collision detection is
// fired every 30 steps at a thin wall it would pass through without it, and
// each step casts a short and a long ray at the column. Checked every step:
// the board world's pair cache holds exactly the pairs a brute-force test
// finds among its proxies' AABBs, every body's transform equals the
// btSimpleBroadphase world's bit for bit (the two caches get the same calls in
// the same order), and so does every ray's closest hit (the board keeps
// Bullet's query contract, which CCD's sweeps and the rays go through:
// docs/bullet.md).
//
//   bullet_app [STEPS]
#include <btBulletDynamicsCommon.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <systemc>

#include "platform/settings/board_preset.h"
#include "platform/kernel.h"
#include "platform/memory_plan.h"
#include "platform/platform_settings.h"
#include "sw/bullet/board_broadphase.h"

namespace {

constexpr int kBodies = 40;
constexpr btScalar kWallX = -3;  // the thin wall the projectile is fired at
constexpr int kShotEvery = 30;   // steps

// A dynamics world on a broad phase of the caller's, with its bodies.
class World {
public:
    explicit World(btBroadphaseInterface& broadphase)
        : dispatcher_(&configuration_), world_(&dispatcher_, &broadphase, &solver_, &configuration_) {
        world_.setGravity(btVector3(0, -9.81f, 0));
        add(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0), 0, btVector3(0, 0, 0));
        auto box = std::make_unique<btBoxShape>(btVector3(0.5f, 0.5f, 0.5f));
        auto sphere = std::make_unique<btSphereShape>(0.5f);
        btCollisionShape* shapes[] = {box.get(), sphere.get()};
        shapes_.push_back(std::move(box));
        shapes_.push_back(std::move(sphere));
        // A loose 4 x 10 column of alternating shapes, offset so they tumble.
        for (int i = 0; i < kBodies; ++i) {
            const btVector3 at(static_cast<float>(i % 4) * 1.1f + 0.05f * static_cast<float>(i % 3),
                               1.0f + static_cast<float>(i / 4) * 1.2f, 0.07f * static_cast<float>(i % 5));
            add_body(shapes[i % 2], 1, at);
        }
        add(std::make_unique<btBoxShape>(btVector3(0.02f, 3, 3)), 0, btVector3(kWallX, 3, 3));
        add(std::make_unique<btSphereShape>(0.1f), 0.2f, btVector3(0, 0, 0));
        projectile_ = bodies_.back();
        projectile_->setCcdMotionThreshold(0.1f);
        projectile_->setCcdSweptSphereRadius(0.08f);
    }
    ~World() {
        for (btRigidBody* body : bodies_) {
            world_.removeRigidBody(body);
            delete body->getMotionState();
            delete body;
        }
    }

    void step() { world_.stepSimulation(1.0f / 60, 1, 1.0f / 60); }
    // From 2 units before the wall at 40 m/s: 0.67 units a step, more than the
    // sphere and the wall together, so it stops only if the CCD sweep sees the wall.
    void fire() {
        projectile_->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(kWallX + 2, 2, 3)));
        projectile_->setLinearVelocity(btVector3(-40, 0, 0));
        projectile_->setAngularVelocity(btVector3(0, 0, 0));
        projectile_->activate();
    }
    bool projectile_before_wall() const { return projectile_->getCenterOfMassPosition().x() > kWallX; }
    // The closest hit of a ray: the body's index and the hit fraction's bits (-1, 1 for none).
    std::pair<int, btScalar> closest_hit(const btVector3& from, const btVector3& to) {
        btCollisionWorld::ClosestRayResultCallback result(from, to);
        world_.rayTest(from, to, result);
        return {result.hasHit() ? result.m_collisionObject->getWorldArrayIndex() : -1, result.m_closestHitFraction};
    }
    const std::vector<btRigidBody*>& bodies() const { return bodies_; }
    int contact_points() {
        int points = 0;
        for (int i = 0; i < dispatcher_.getNumManifolds(); ++i) {
            points += dispatcher_.getManifoldByIndexInternal(i)->getNumContacts();
        }
        return points;
    }

private:
    void add(std::unique_ptr<btCollisionShape> shape, btScalar mass, const btVector3& at) {
        add_body(shape.get(), mass, at);
        shapes_.push_back(std::move(shape));
    }
    void add_body(btCollisionShape* shape, btScalar mass, const btVector3& at) {
        btVector3 inertia(0, 0, 0);
        if (mass > 0) shape->calculateLocalInertia(mass, inertia);
        auto* motion = new btDefaultMotionState(btTransform(btQuaternion::getIdentity(), at));
        auto* body = new btRigidBody(btRigidBody::btRigidBodyConstructionInfo(mass, motion, shape, inertia));
        world_.addRigidBody(body);
        bodies_.push_back(body);
    }

    btDefaultCollisionConfiguration configuration_;
    btCollisionDispatcher dispatcher_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<btRigidBody*> bodies_;
    btRigidBody* projectile_ = nullptr;
};

// Overlapping pairs among boxes, closed intervals, by brute force, but for
// pairs of two static boxes, which Bullet's default filter keeps out of the cache.
std::size_t brute_force_pairs(const std::vector<cdvp::FloatBox>& boxes, const std::vector<bool>& is_static) {
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            if (is_static[i] && is_static[j]) continue;
            bool overlap = true;
            for (int a = 0; a < 3; ++a) {
                overlap = overlap && boxes[i].min[a] <= boxes[j].max[a] && boxes[j].min[a] <= boxes[i].max[a];
            }
            pairs += overlap ? 1 : 0;
        }
    }
    return pairs;
}

bool same_transform(const btRigidBody& a, const btRigidBody& b) {
    btTransformFloatData x, y;
    a.getWorldTransform().serializeFloat(x);
    b.getWorldTransform().serializeFloat(y);
    return std::memcmp(&x, &y, sizeof x) == 0;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    cdvp::configure_kernel();  // the virtual board elaborates on the first step
    const int steps = argc > 1 ? std::stoi(argv[1]) : 120;
    constexpr uint32_t kCapacity = kBodies + 3;  // and the ground plane, the wall and the projectile
    const cdvp::SettingValues settings = cdvp::load_board_preset(std::string(CDVP_BOARDS_DIR) + "/adm-xrc-ii.json").applied();
    cdvp::PlatformConfig config = cdvp::platform_config(settings);
    config.board = cdvp::planned_board(settings.settings(), kCapacity);

    cdvp::LazyVirtualBoard board(config, kCapacity);
    cdvp::BoardBroadphase board_broadphase(board);
    btSimpleBroadphase simple_broadphase(2 * kCapacity);
    World on_board(board_broadphase), on_simple(simple_broadphase);

    int failures = 0, shots = 0, stopped = 0, rays = 0, ray_hits = 0;
    double board_ns = 0;
    std::size_t pairs = 0;
    for (int step = 0; step < steps; ++step) {
        if (step % kShotEvery == 0) {
            stopped += step > 0 && on_board.projectile_before_wall() ? 1 : 0;
            on_board.fire();
            on_simple.fire();
            ++shots;
        }
        on_board.step();
        on_simple.step();
        const std::size_t cached = board_broadphase.getOverlappingPairCache()->getNumOverlappingPairs();
        std::vector<bool> is_static(board_broadphase.last_boxes().size(), false);
        for (const btRigidBody* body : on_board.bodies()) {
            if (body->isStaticObject()) is_static[board_broadphase.board_index(body->getBroadphaseHandle())] = true;
        }
        const std::size_t expected = brute_force_pairs(board_broadphase.last_boxes(), is_static);
        std::size_t identical = 0;
        for (std::size_t i = 0; i < on_board.bodies().size(); ++i) {
            identical += same_transform(*on_board.bodies()[i], *on_simple.bodies()[i]) ? 1 : 0;
        }
        // A short ray (0.8 units) and a long one (12) down onto the column.
        bool same_hits = true;
        const btVector3 above(1.5f + 0.1f * static_cast<float>(step % 20), 2.5f, 0.1f);
        for (const btScalar length : {0.8f, 12.0f}) {
            const btVector3 to = above - btVector3(0, length, 0);
            const auto hit = on_board.closest_hit(above, to);
            same_hits = same_hits && hit == on_simple.closest_hit(above, to);
            ++rays;
            ray_hits += hit.first >= 0 ? 1 : 0;
        }
        const bool ok = cached == expected && identical == on_board.bodies().size() && same_hits;
        failures += ok ? 0 : 1;
        if (!ok || step % 30 == 0 || step == steps - 1) {
            std::printf("step %3d: %zu pairs cached, %zu by brute force; %zu of %zu bodies bit-identical to "
                        "btSimpleBroadphase; rays %s; %d contact points; %.1f us on the board\n",
                        step, cached, expected, identical, on_board.bodies().size(),
                        same_hits ? "the same" : "DIFFER", on_board.contact_points(),
                        board_broadphase.last_frame().phases.total_ns / 1e3);
        }
        board_ns += board_broadphase.last_frame().phases.total_ns;
        pairs += cached;
    }
    const btVector3 lowest = on_board.bodies()[1]->getCenterOfMassPosition();
    stopped += on_board.projectile_before_wall() ? 1 : 0;
    std::printf("%d steps, %d bodies, %zu pairs, %d failing steps; %.1f us a step on the board; body 1 at y=%.3f\n",
                steps, kBodies, pairs, failures, board_ns / steps / 1e3, static_cast<double>(lowest.y()));
    std::printf("%d rays, %d hits, the same as btSimpleBroadphase's; the CCD projectile stopped by the wall %d times "
                "of %d\n", rays, ray_hits, stopped, shots);
    return failures == 0 && stopped == shots ? 0 : 1;
}
