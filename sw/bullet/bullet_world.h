// A btDiscreteDynamicsWorld on a broad phase of the caller's choice, owning
// its shapes and bodies, stepped at a fixed 1/60 s with the time of each
// collision stage measured (the broad phase's share of a step is the most an
// accelerator of it can win).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sw/bullet/board_link.h"
#include "sw/scene/scene.h"

namespace cdvp {

enum class BroadphaseKind { kSimple, kSap, kDbvt, kBoard };
const char* to_string(BroadphaseKind kind);
// "simple", "sap", "dbvt", "board"; std::invalid_argument otherwise.
BroadphaseKind broadphase_kind(const std::string& name);

// World bounds are btAxisSweep3's quantization range (ignored by the others);
// proxies: how many the scene starts with (btSimpleBroadphase and btAxisSweep3
// get room for twice as many, at least their default 16,384); the board needs
// its link (shared, outliving the broad phase), whose capacity bounds it.
std::unique_ptr<btBroadphaseInterface> make_broadphase(BroadphaseKind kind, const btVector3& world_min,
                                                       const btVector3& world_max, uint32_t proxies,
                                                       BoardLink* link);

// Wall times of one step, in ns (steady clock).
struct StepTimes {
    double aabbs_ns = 0;         // updateAabbs: every object's AABB handed to the broad phase
    double broadphase_ns = 0;    // calculateOverlappingPairs
    double narrowphase_ns = 0;   // the dispatcher over the pair cache
    double step_ns = 0;          // the whole stepSimulation
    // Each time above is the thread's CPU time; the step's wall time beside
    // it, and whether a pre-emption or a move to another CPU disturbed it.
    double step_wall_ns = 0;
    bool disturbed = false;
    // What a broad phase accounts for: its setAabb work rides in updateAabbs.
    double broadphase_share_ns() const { return aabbs_ns + broadphase_ns; }
};

class BulletWorld {
public:
    explicit BulletWorld(std::unique_ptr<btBroadphaseInterface> broadphase);
    ~BulletWorld();
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;

    // Takes the shape; returns it for add_body.
    btCollisionShape* keep_shape(std::unique_ptr<btCollisionShape> shape);
    // mass 0 makes a static body. Group and mask as btDiscreteDynamicsWorld's addRigidBody.
    btRigidBody* add_body(btCollisionShape* shape, btScalar mass, const btTransform& transform,
                          int group = btBroadphaseProxy::DefaultFilter, int mask = btBroadphaseProxy::AllFilter);
    // Removes the body from the world (its proxy is destroyed) and frees it.
    void remove_body(btRigidBody* body);

    // One fixed step of 1/60 s.
    StepTimes step();
    uint64_t steps() const { return steps_; }

    // Contact points in all manifolds after the last step.
    std::size_t contact_points() const;
    // Sum over dynamic bodies of 1/2 m v^2 + 1/2 w.I w.
    double kinetic_energy() const;
    // Bodies not sleeping (ISLAND_SLEEPING); static bodies do not count.
    std::size_t awake_bodies() const;
    // Every collision object's broad-phase AABB, ids 0..n-1 in the world's order.
    Frame aabbs(uint64_t number) const;

    btDiscreteDynamicsWorld& world();
    const btDiscreteDynamicsWorld& world() const;
    btBroadphaseInterface& broadphase() { return *broadphase_; }
    const std::vector<btRigidBody*>& bodies() const { return bodies_; }

private:
    class TimedWorld;

    std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btBroadphaseInterface> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<TimedWorld> world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<btRigidBody*> bodies_;
    uint64_t steps_ = 0;
};

}  // namespace cdvp
