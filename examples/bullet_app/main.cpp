// A few dozen boxes and spheres falling on a ground plane, in a plain
// btDiscreteDynamicsWorld whose broad phase is cdvp's board (the paper's
// ADM-XRC-II preset), stepped beside the same world on btSimpleBroadphase.
// Checked every step: the board world's pair cache holds exactly the pairs a
// brute-force test finds among its proxies' AABBs, and every body's
// transform equals the btSimpleBroadphase world's bit for bit (the two caches
// get the same calls in the same order: docs/bullet.md).
//
//   bullet_app [STEPS]
#include <btBulletDynamicsCommon.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <systemc>

#include "platform/settings/board_preset.h"
#include "platform/kernel.h"
#include "platform/memory_plan.h"
#include "platform/platform_settings.h"
#include "sw/bullet/board_broadphase.h"

namespace {

constexpr int kBodies = 40;

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
    }
    ~World() {
        for (btRigidBody* body : bodies_) {
            world_.removeRigidBody(body);
            delete body->getMotionState();
            delete body;
        }
    }

    void step() { world_.stepSimulation(1.0f / 60, 1, 1.0f / 60); }
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
};

// Overlapping pairs among boxes, closed intervals, by brute force.
std::size_t brute_force_pairs(const std::vector<cdvp::FloatBox>& boxes) {
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
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
    constexpr uint32_t kCapacity = kBodies + 1;  // and the ground plane
    const cdvp::SettingValues settings = cdvp::load_board_preset(std::string(CDVP_BOARDS_DIR) + "/adm-xrc-ii.json").applied();
    cdvp::PlatformConfig config = cdvp::platform_config(settings);
    config.board = cdvp::planned_board(settings.settings(), kCapacity);

    cdvp::LazyVirtualBoard board(config, kCapacity);
    cdvp::BoardBroadphase board_broadphase(board);
    btSimpleBroadphase simple_broadphase(2 * kCapacity);
    World on_board(board_broadphase), on_simple(simple_broadphase);

    int failures = 0;
    double board_ns = 0;
    std::size_t pairs = 0;
    for (int step = 0; step < steps; ++step) {
        on_board.step();
        on_simple.step();
        const std::size_t cached = board_broadphase.getOverlappingPairCache()->getNumOverlappingPairs();
        const std::size_t expected = brute_force_pairs(board_broadphase.last_boxes());
        std::size_t identical = 0;
        for (std::size_t i = 0; i < on_board.bodies().size(); ++i) {
            identical += same_transform(*on_board.bodies()[i], *on_simple.bodies()[i]) ? 1 : 0;
        }
        const bool ok = cached == expected && identical == on_board.bodies().size();
        failures += ok ? 0 : 1;
        if (!ok || step % 30 == 0 || step == steps - 1) {
            std::printf("step %3d: %zu pairs cached, %zu by brute force; %zu of %zu bodies bit-identical to "
                        "btSimpleBroadphase; %d contact points; %.1f us on the board\n",
                        step, cached, expected, identical, on_board.bodies().size(), on_board.contact_points(),
                        board_broadphase.last_frame().phases.total_ns / 1e3);
        }
        board_ns += board_broadphase.last_frame().phases.total_ns;
        pairs += cached;
    }
    const btVector3 lowest = on_board.bodies()[1]->getCenterOfMassPosition();
    std::printf("%d steps, %d bodies, %zu pairs, %d failing steps; %.1f us a step on the board; body 1 at y=%.3f\n",
                steps, kBodies, pairs, failures, board_ns / steps / 1e3, static_cast<double>(lowest.y()));
    return failures == 0 ? 0 : 1;
}
