// Shared checks for the Bullet tests: pair sets by unique id, the exact set
// the cache must hold, and bitwise comparisons of two worlds.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <utility>
#include <vector>

#include "sw/bullet/board_broadphase.h"
#include "sw/bullet/bullet_world.h"

namespace cdvp::testing {

using UidPairs = std::set<std::pair<int, int>>;

inline std::pair<int, int> uid_pair(const btBroadphaseProxy* a, const btBroadphaseProxy* b) {
    return std::minmax(a->getUid(), b->getUid());
}

inline UidPairs cached_pairs(const btOverlappingPairCache& cache) {
    UidPairs pairs;
    const btBroadphasePairArray& array = const_cast<btOverlappingPairCache&>(cache).getOverlappingPairArray();
    for (int k = 0; k < array.size(); ++k) pairs.insert(uid_pair(array[k].m_pProxy0, array[k].m_pProxy1));
    return pairs;
}

inline bool float_boxes_overlap(const btBroadphaseProxy& a, const btBroadphaseProxy& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(a.m_aabbMin[axis] <= b.m_aabbMax[axis] && b.m_aabbMin[axis] <= a.m_aabbMax[axis])) return false;
    }
    return true;
}

// Brute force over the world's proxies: every closed float overlap the cache's
// filter accepts (filtered = false: every overlap).
inline UidPairs exact_pairs(const btCollisionWorld& world, bool filtered = true) {
    UidPairs pairs;
    const btCollisionObjectArray& objects = world.getCollisionObjectArray();
    const btOverlappingPairCache* cache = world.getBroadphase()->getOverlappingPairCache();
    for (int i = 0; i < objects.size(); ++i) {
        for (int j = i + 1; j < objects.size(); ++j) {
            btBroadphaseProxy* a = objects[i]->getBroadphaseHandle();
            btBroadphaseProxy* b = objects[j]->getBroadphaseHandle();
            if (!float_boxes_overlap(*a, *b)) continue;
            if (filtered && !cache->needsBroadphaseCollision(a, b)) continue;
            pairs.insert(uid_pair(a, b));
        }
    }
    return pairs;
}

template <typename T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Every body's transform and velocities, bit for bit; the first difference is reported.
inline ::testing::AssertionResult same_state(BulletWorld& a, BulletWorld& b) {
    if (a.bodies().size() != b.bodies().size()) return ::testing::AssertionFailure() << "body counts differ";
    for (std::size_t k = 0; k < a.bodies().size(); ++k) {
        const btRigidBody& x = *a.bodies()[k];
        const btRigidBody& y = *b.bodies()[k];
        const btTransform& tx = x.getWorldTransform();
        const btTransform& ty = y.getWorldTransform();
        bool same = same_bits(tx.getOrigin(), ty.getOrigin()) &&
                    same_bits(x.getLinearVelocity(), y.getLinearVelocity()) &&
                    same_bits(x.getAngularVelocity(), y.getAngularVelocity());
        for (int row = 0; row < 3; ++row) same = same && same_bits(tx.getBasis()[row], ty.getBasis()[row]);
        if (!same) return ::testing::AssertionFailure() << "body " << k << " differs";
    }
    return ::testing::AssertionSuccess();
}

}  // namespace cdvp::testing
