// Shared checks for the Bullet tests: pair sets by unique id, the exact set
// the cache must hold, and bitwise comparisons of two worlds (bodies, contacts).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
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

// Every contact point of every manifold (predictive ones too), by the two
// bodies' indices in the world, bit for bit. Manifolds are compared as sorted
// sets: other broad phases create them in another order.
inline ::testing::AssertionResult same_contacts(const btCollisionWorld& a, const btCollisionWorld& b) {
    using Point = std::vector<unsigned char>;
    const auto points = [](const btCollisionWorld& world) {
        std::vector<std::pair<std::pair<int, int>, Point>> all;
        btDispatcher* dispatcher = const_cast<btCollisionWorld&>(world).getDispatcher();
        for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
            const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
            const std::pair<int, int> bodies(manifold->getBody0()->getWorldArrayIndex(),
                                             manifold->getBody1()->getWorldArrayIndex());
            for (int k = 0; k < manifold->getNumContacts(); ++k) {
                const btManifoldPoint& point = manifold->getContactPoint(k);
                Point bits;
                for (const btVector3* v : {&point.m_positionWorldOnA, &point.m_positionWorldOnB, &point.m_normalWorldOnB}) {
                    const auto* bytes = reinterpret_cast<const unsigned char*>(v);
                    bits.insert(bits.end(), bytes, bytes + 3 * sizeof(btScalar));
                }
                const auto* distance = reinterpret_cast<const unsigned char*>(&point.m_distance1);
                bits.insert(bits.end(), distance, distance + sizeof(btScalar));
                all.emplace_back(bodies, std::move(bits));
            }
        }
        std::sort(all.begin(), all.end());
        return all;
    };
    const auto x = points(a), y = points(b);
    if (x.size() != y.size()) {
        return ::testing::AssertionFailure() << x.size() << " contact points against " << y.size();
    }
    for (std::size_t k = 0; k < x.size(); ++k) {
        if (x[k] != y[k]) {
            return ::testing::AssertionFailure() << "a contact point of bodies " << x[k].first.first << " and "
                                                 << x[k].first.second << " differs";
        }
    }
    return ::testing::AssertionSuccess();
}

}  // namespace cdvp::testing
