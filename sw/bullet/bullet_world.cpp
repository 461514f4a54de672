#include "sw/bullet/bullet_world.h"

#include <BulletCollision/BroadphaseCollision/btSimpleBroadphase.h>

#include <algorithm>
#include <stdexcept>

#include "sw/baselines/bullet_factory.h"
#include "sw/bullet/board_broadphase.h"
#include "sw/timing/thread_timer.h"

namespace cdvp {

namespace {

// The stages are timed in the thread's CPU time, as the whole step is.
double ns_between(int64_t start, int64_t end) { return static_cast<double>(end - start); }

constexpr btScalar kStep = btScalar(1.0 / 60.0);
constexpr uint64_t kDefaultHandles = 16384;  // btSimpleBroadphase's and btAxisSweep3's default

}  // namespace

const char* to_string(BroadphaseKind kind) {
    switch (kind) {
        case BroadphaseKind::kSimple: return "simple";
        case BroadphaseKind::kSap: return "sap";
        case BroadphaseKind::kDbvt: return "dbvt";
        case BroadphaseKind::kBoard: return "board";
    }
    return "?";
}

BroadphaseKind broadphase_kind(const std::string& name) {
    for (BroadphaseKind kind : {BroadphaseKind::kSimple, BroadphaseKind::kSap, BroadphaseKind::kDbvt,
                                BroadphaseKind::kBoard}) {
        if (name == to_string(kind)) return kind;
    }
    throw std::invalid_argument("unknown broad phase '" + name + "'; expected simple, sap, dbvt or board");
}

std::unique_ptr<btBroadphaseInterface> make_broadphase(BroadphaseKind kind, const btVector3& world_min,
                                                       const btVector3& world_max, uint32_t proxies,
                                                       BoardLink* link) {
    // Room for twice the proxies the scene starts with, as it adds more.
    const uint64_t handles = std::max<uint64_t>(kDefaultHandles, 2 * uint64_t{proxies});
    if (handles > INT32_MAX) throw std::invalid_argument("too many proxies for Bullet's broad phases");
    constexpr bool kRayAccelerator = true;  // Bullet's default: the scenes may cast rays
    switch (kind) {
        case BroadphaseKind::kSimple: return std::make_unique<btSimpleBroadphase>(static_cast<int>(handles));
        case BroadphaseKind::kSap:
            return make_bt_broadphase(BulletKind::sap, world_min, world_max, handles, kRayAccelerator);
        case BroadphaseKind::kDbvt:
            return make_bt_broadphase(BulletKind::dbvt, world_min, world_max, handles, kRayAccelerator);
        case BroadphaseKind::kBoard:
            if (link == nullptr) throw std::invalid_argument("the board broad phase needs a board link");
            return std::make_unique<BoardBroadphase>(*link);
    }
    throw std::invalid_argument("unknown broad phase kind");
}

// btCollisionWorld's collision detection, the same three stages in the same
// order, with a CPU-time clock read between them.
class BulletWorld::TimedWorld : public btDiscreteDynamicsWorld {
public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    StepTimes times;

    void performDiscreteCollisionDetection() override {
        const int64_t start = thread_cpu_ns();
        updateAabbs();
        const int64_t aabbs_done = thread_cpu_ns();
        computeOverlappingPairs();
        const int64_t pairs_done = thread_cpu_ns();
        if (btDispatcher* dispatcher = getDispatcher()) {
            dispatcher->dispatchAllCollisionPairs(getBroadphase()->getOverlappingPairCache(), getDispatchInfo(),
                                                  dispatcher);
        }
        const int64_t end = thread_cpu_ns();
        times.aabbs_ns += ns_between(start, aabbs_done);
        times.broadphase_ns += ns_between(aabbs_done, pairs_done);
        times.narrowphase_ns += ns_between(pairs_done, end);
    }
};

BulletWorld::BulletWorld(std::unique_ptr<btBroadphaseInterface> broadphase)
    : configuration_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::move(broadphase)),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<TimedWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(), configuration_.get())) {}

BulletWorld::~BulletWorld() {
    // Newest first: a broad phase that reuses slots last-freed-first then ends empty.
    while (!bodies_.empty()) remove_body(bodies_.back());
    world_.reset();
}

btDiscreteDynamicsWorld& BulletWorld::world() { return *world_; }
const btDiscreteDynamicsWorld& BulletWorld::world() const { return *world_; }

btCollisionShape* BulletWorld::keep_shape(std::unique_ptr<btCollisionShape> shape) {
    shapes_.push_back(std::move(shape));
    return shapes_.back().get();
}

btRigidBody* BulletWorld::add_body(btCollisionShape* shape, btScalar mass, const btTransform& transform, int group,
                                   int mask) {
    btVector3 inertia(0, 0, 0);
    if (mass != 0) shape->calculateLocalInertia(mass, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape, inertia);
    info.m_startWorldTransform = transform;
    auto* body = new btRigidBody(info);
    world_->addRigidBody(body, group, mask);
    bodies_.push_back(body);
    return body;
}

void BulletWorld::remove_body(btRigidBody* body) {
    const auto found = std::find(bodies_.begin(), bodies_.end(), body);
    if (found == bodies_.end()) throw std::invalid_argument("remove_body: not a body of this world");
    world_->removeRigidBody(body);
    bodies_.erase(found);
    delete body;
}

StepTimes BulletWorld::step() {
    world_->times = StepTimes{};
    const CallTiming timing = CallTimer::time([this] {
        world_->stepSimulation(kStep, 0);  // no substeps: exactly one internal step of kStep
    });
    world_->times.step_ns = timing.cpu_ns;
    world_->times.step_wall_ns = timing.wall_ns;
    world_->times.disturbed = timing.disturbed();
    ++steps_;
    return world_->times;
}

std::size_t BulletWorld::contact_points() const {
    std::size_t points = 0;
    const int manifolds = dispatcher_->getNumManifolds();
    for (int k = 0; k < manifolds; ++k) {
        points += static_cast<std::size_t>(dispatcher_->getManifoldByIndexInternal(k)->getNumContacts());
    }
    return points;
}

double BulletWorld::kinetic_energy() const {
    double energy = 0;
    for (const btRigidBody* body : bodies_) {
        if (body->getInvMass() == 0) continue;
        const btVector3& v = body->getLinearVelocity();
        energy += 0.5 * static_cast<double>(v.length2()) / static_cast<double>(body->getInvMass());
        // In the body's principal frame the inertia is diagonal: 1/2 sum I_k w_k^2.
        const btVector3 w = body->getWorldTransform().getBasis().transpose() * body->getAngularVelocity();
        const btVector3& inverse_inertia = body->getInvInertiaDiagLocal();
        for (int axis = 0; axis < 3; ++axis) {
            if (inverse_inertia[axis] != 0) {
                energy += 0.5 * static_cast<double>(w[axis] * w[axis]) / static_cast<double>(inverse_inertia[axis]);
            }
        }
    }
    return energy;
}

std::size_t BulletWorld::awake_bodies() const {
    std::size_t awake = 0;
    for (const btRigidBody* body : bodies_) {
        if (body->getInvMass() != 0 && body->getActivationState() != ISLAND_SLEEPING) ++awake;
    }
    return awake;
}

Frame BulletWorld::aabbs(uint64_t number) const {
    Frame frame;
    frame.number = number;
    const btCollisionObjectArray& objects = world_->getCollisionObjectArray();
    for (int k = 0; k < objects.size(); ++k) {
        const btBroadphaseProxy* proxy = objects[k]->getBroadphaseHandle();
        Box box;
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = proxy->m_aabbMin[axis];
            box.max[axis] = proxy->m_aabbMax[axis];
        }
        frame.ids.push_back(static_cast<uint64_t>(k));
        frame.boxes.push_back(box);
    }
    return frame;
}

}  // namespace cdvp
