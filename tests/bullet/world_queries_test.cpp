// btCollisionWorld's queries on the board's broad phase: rayTest (closest and
// all hits), convexSweepTest and contactTest, short (< 1 unit) and long, on
// the same world on the board (fast engine), btSimpleBroadphase and
// btDbvtBroadphase, compared bit for bit (docs/bullet.md, "The query
// contract", says where btDbvtBroadphase may differ and why). The bodies are
// placed anew each round (not stepped), so the three worlds hold the same
// bodies whatever order their broad phases hand pairs over in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <random>
#include <vector>

#include <LinearMath/btAabbUtil2.h>

#include "sw/bullet/bullet_world.h"
#include "tests/bullet/bullet_test_support.h"

namespace cdvp {
namespace {

constexpr int kBodies = 80;
constexpr int kRounds = 5;
constexpr int kQueries = 40;  // of each kind, per round: half short, half long

// A result's indices and floats, each as its 32 bits.
using Bits = std::vector<uint32_t>;

template <typename T>
void append(Bits& bits, const T& value) {
    static_assert(sizeof(T) == sizeof(uint32_t), "btScalar is float in Debian's Bullet");
    uint32_t word = 0;
    std::memcpy(&word, &value, sizeof word);
    bits.push_back(word);
}
void append_vector(Bits& bits, const btVector3& v) {
    for (int axis = 0; axis < 3; ++axis) append(bits, v[axis]);
}
int index_of(const btCollisionObject* object) { return object == nullptr ? -1 : object->getWorldArrayIndex(); }
const btCollisionObject* object_at(BulletWorld& world, int index) {
    return world.world().getCollisionObjectArray()[index];
}

// A closest-hit callback that sees one object only (any, when null).
template <typename Callback>
struct OnlyObject : Callback {
    OnlyObject(const btVector3& from, const btVector3& to, const btCollisionObject* only)
        : Callback(from, to), only_(only) {}
    bool needsCollision(btBroadphaseProxy* proxy) const override {
        return (only_ == nullptr || proxy->m_clientObject == only_) && Callback::needsCollision(proxy);
    }
    const btCollisionObject* only_;
};

// A hit: [object index, fraction, normal, point]; a miss: [-1, fraction].
Bits hit_bits(const btCollisionObject* object, btScalar fraction, const btVector3& normal, const btVector3& point) {
    Bits bits;
    append(bits, index_of(object));
    append(bits, fraction);
    if (object != nullptr) {
        append_vector(bits, normal);
        append_vector(bits, point);
    }
    return bits;
}

Bits closest_ray(BulletWorld& world, const btVector3& from, const btVector3& to,
                 const btCollisionObject* only = nullptr) {
    OnlyObject<btCollisionWorld::ClosestRayResultCallback> result(from, to, only);
    world.world().rayTest(from, to, result);
    return hit_bits(result.m_collisionObject, result.m_closestHitFraction, result.m_hitNormalWorld,
                    result.m_hitPointWorld);
}

std::vector<Bits> all_hits(BulletWorld& world, const btVector3& from, const btVector3& to) {
    btCollisionWorld::AllHitsRayResultCallback result(from, to);
    world.world().rayTest(from, to, result);
    std::vector<Bits> hits;
    for (int k = 0; k < result.m_collisionObjects.size(); ++k) {
        hits.push_back(hit_bits(result.m_collisionObjects[k], result.m_hitFractions[k], result.m_hitNormalWorld[k],
                                result.m_hitPointWorld[k]));
    }
    return hits;
}

Bits closest_sweep(BulletWorld& world, const btConvexShape& shape, const btTransform& from, const btTransform& to,
                   const btCollisionObject* only = nullptr) {
    OnlyObject<btCollisionWorld::ClosestConvexResultCallback> result(from.getOrigin(), to.getOrigin(), only);
    world.world().convexSweepTest(&shape, from, to, result);
    return hit_bits(result.m_hitCollisionObject, result.m_closestHitFraction, result.m_hitNormalWorld,
                    result.m_hitPointWorld);
}

// Two closest hits agree, or tie: the same fraction, and the other's object,
// queried alone in the first's world, hit at that fraction as the other says.
// (At equal fractions the closest-hit callbacks keep the object they were
// handed first: btSimpleBroadphase's and the board's order is one, btDbvt's another.)
template <typename Query>
::testing::AssertionResult same_or_tie(const Bits& board, const Bits& other, Query alone, int& ties) {
    if (board == other) return ::testing::AssertionSuccess();
    if (board[1] != other[1]) return ::testing::AssertionFailure() << "the closest fractions differ";
    const auto object = static_cast<int32_t>(other[0]);
    if (object < 0 || alone(object) != other) {
        return ::testing::AssertionFailure() << "object " << object << " is not hit as the other world says";
    }
    ++ties;
    return ::testing::AssertionSuccess();
}

struct ContactRecorder : btCollisionWorld::ContactResultCallback {
    btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                             const btCollisionObjectWrapper* b, int, int) override {
        Bits bits;
        append(bits, index_of(a->getCollisionObject()));
        append(bits, index_of(b->getCollisionObject()));
        append_vector(bits, point.m_positionWorldOnB);
        append_vector(bits, point.m_normalWorldOnB);
        append(bits, point.m_distance1);
        contacts.push_back(bits);
        return 0;
    }
    std::vector<Bits> contacts;
};

std::vector<Bits> contacts_of(BulletWorld& world, int body) {
    ContactRecorder recorder;
    world.world().contactTest(world.bodies()[body], recorder);
    return recorder.contacts;
}

std::vector<Bits> sorted(std::vector<Bits> bits) {
    std::sort(bits.begin(), bits.end());
    return bits;
}

// A ground plane, a few static boxes, and bodies of four shapes.
void build(BulletWorld& world) {
    btCollisionShape* plane = world.keep_shape(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0));
    world.add_body(plane, 0, btTransform::getIdentity());
    btCollisionShape* block = world.keep_shape(std::make_unique<btBoxShape>(btVector3(1, 0.5f, 2)));
    for (int k = 0; k < 4; ++k) {
        world.add_body(block, 0, btTransform(btQuaternion::getIdentity(), btVector3(btScalar(k) * 3 - 4.5f, 0.5f, 4)));
    }
    btCollisionShape* shapes[] = {
        world.keep_shape(std::make_unique<btSphereShape>(0.15f)),
        world.keep_shape(std::make_unique<btSphereShape>(0.5f)),
        world.keep_shape(std::make_unique<btBoxShape>(btVector3(0.1f, 0.3f, 0.2f))),
        world.keep_shape(std::make_unique<btCapsuleShape>(0.1f, 0.6f)),
        world.keep_shape(std::make_unique<btCylinderShape>(btVector3(0.3f, 0.1f, 0.3f)))};
    for (int k = 0; k < kBodies; ++k) world.add_body(shapes[k % 5], 1, btTransform::getIdentity());
}

btQuaternion random_rotation(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    return btQuaternion(normal(rng), normal(rng), normal(rng), normal(rng) + 0.01f).normalized();
}

btVector3 random_direction(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    return btVector3(normal(rng), normal(rng), normal(rng) + 0.01f).normalized();
}

// Every dynamic body placed at random, the same in each world, then one
// collision pass (on the board: a frame) so that the broad phases hold the new boxes.
void place(const std::vector<BulletWorld*>& worlds, std::mt19937& rng) {
    std::uniform_real_distribution<float> horizontal(-6, 6), height(0.2f, 5);
    const std::size_t first_dynamic = 5;
    for (std::size_t k = first_dynamic; k < worlds[0]->bodies().size(); ++k) {
        const btTransform pose(random_rotation(rng), btVector3(horizontal(rng), height(rng), horizontal(rng)));
        for (BulletWorld* world : worlds) world->bodies()[k]->setWorldTransform(pose);
    }
    for (BulletWorld* world : worlds) world->world().performDiscreteCollisionDetection();
}

// A segment aimed at a random body: from beside its box, of the given length.
std::pair<btVector3, btVector3> aimed_segment(BulletWorld& world, std::mt19937& rng, float length) {
    std::uniform_int_distribution<int> body(5, 4 + kBodies);
    btVector3 lo, hi;
    world.bodies()[body(rng)]->getAabb(lo, hi);
    const btVector3 centre = (lo + hi) / 2;
    const btVector3 from = centre + random_direction(rng) * ((hi - lo).length() / 2 + length / 3);
    const btVector3 to = from + ((centre - from).normalized() + random_direction(rng) * 0.2f).normalized() * length;
    return {from, to};
}

class WorldQueries : public ::testing::Test {
protected:
    WorldQueries() : link_(platform(), kBodies + 5) {
        board_ = make(BroadphaseKind::kBoard, &link_);
        simple_ = make(BroadphaseKind::kSimple, nullptr);
        dbvt_ = make(BroadphaseKind::kDbvt, nullptr);
    }
    static PlatformConfig platform() {
        PlatformConfig config;
        config.board.m = 8;
        config.fidelity = Fidelity::kFast;
        return config;
    }
    static std::unique_ptr<BulletWorld> make(BroadphaseKind kind, BoardLink* link) {
        auto world = std::make_unique<BulletWorld>(
            make_broadphase(kind, btVector3(-20, -20, -20), btVector3(20, 20, 20), kBodies + 5, link));
        build(*world);
        return world;
    }
    std::vector<BulletWorld*> worlds() { return {board_.get(), simple_.get(), dbvt_.get()}; }
    // Short segments (0.05 to 1 unit) aimed at bodies, then long ones (1 to 20) across the scene.
    std::pair<btVector3, btVector3> segment(int query) {
        if (query < kQueries / 2) return aimed_segment(*board_, rng_, std::uniform_real_distribution<float>(0.05f, 1)(rng_));
        std::uniform_real_distribution<float> horizontal(-8, 8), height(-0.5f, 6), length(1, 20);
        const btVector3 from(horizontal(rng_), height(rng_), horizontal(rng_));
        return {from, from + random_direction(rng_) * length(rng_)};
    }

    LazyVirtualBoard link_;
    std::unique_ptr<BulletWorld> board_, simple_, dbvt_;
    std::mt19937 rng_{31};
};

TEST_F(WorldQueries, RayTestsShortAndLongAreBitIdentical) {
    int short_hits = 0, long_hits = 0, multi_hits = 0, ties = 0;
    for (int round = 0; round < kRounds; ++round) {
        place(worlds(), rng_);
        for (int query = 0; query < kQueries; ++query) {
            const auto ends = segment(query);  // not a structured binding: lambdas below capture them
            const auto& from = ends.first;
            const auto& to = ends.second;
            const Bits closest = closest_ray(*board_, from, to);
            ASSERT_EQ(closest, closest_ray(*simple_, from, to)) << "round " << round << " ray " << query;
            ASSERT_TRUE(same_or_tie(closest, closest_ray(*dbvt_, from, to),
                                    [&](int object) { return closest_ray(*board_, from, to, object_at(*board_, object)); },
                                    ties))
                << "round " << round << " ray " << query;
            const std::vector<Bits> all = all_hits(*board_, from, to);
            ASSERT_EQ(all, all_hits(*simple_, from, to)) << "in btSimpleBroadphase's order; round " << round;
            ASSERT_EQ(sorted(all), sorted(all_hits(*dbvt_, from, to))) << "round " << round << " ray " << query;
            (query < kQueries / 2 ? short_hits : long_hits) += all.empty() ? 0 : 1;
            multi_hits += all.size() > 1 ? 1 : 0;
        }
    }
    std::printf("%d rays: %d short and %d long ones hit, %d hit more than one body, %d ties on btDbvtBroadphase\n",
                kRounds * kQueries, short_hits, long_hits, multi_hits, ties);
    EXPECT_GT(short_hits, kRounds * kQueries / 8) << "short rays should hit the bodies they aim at";
    EXPECT_GT(long_hits, kRounds * kQueries / 8);
    EXPECT_GT(multi_hits, 0);
}

TEST_F(WorldQueries, ConvexSweepsShortAndLongAreBitIdentical) {
    const btSphereShape ball(0.15f);
    const btBoxShape brick(btVector3(0.1f, 0.2f, 0.3f));
    int hits = 0, ties = 0;
    for (int round = 0; round < kRounds; ++round) {
        place(worlds(), rng_);
        for (int query = 0; query < kQueries; ++query) {
            const auto [from, to] = segment(query);
            const btConvexShape& shape = query % 2 ? static_cast<const btConvexShape&>(ball) : brick;
            // The brick turns on its way, so its swept box grows.
            const btQuaternion turn = random_rotation(rng_);
            const btTransform start(turn, from), end(query % 4 == 0 ? turn * random_rotation(rng_) : turn, to);
            const Bits board = closest_sweep(*board_, shape, start, end);
            ASSERT_EQ(board, closest_sweep(*simple_, shape, start, end)) << "round " << round << " sweep " << query;
            ASSERT_TRUE(same_or_tie(board, closest_sweep(*dbvt_, shape, start, end),
                                    [&](int object) {
                                        return closest_sweep(*board_, shape, start, end, object_at(*board_, object));
                                    },
                                    ties))
                << "round " << round << " sweep " << query;
            hits += static_cast<int32_t>(board[0]) >= 0 ? 1 : 0;
        }
    }
    std::printf("%d sweeps: %d hit, %d ties on btDbvtBroadphase\n", kRounds * kQueries, hits, ties);
    EXPECT_GT(hits, kRounds * kQueries / 4);
}

// contactTest reports what the narrow phase finds among the bodies aabbTest
// hands it. The board hands btSimpleBroadphase's bodies in its order; btDbvt's
// grown leaves may hand more, and the narrow phase finds points up to the
// contact threshold beyond the boxes: those extra points belong to bodies
// whose box does not meet the query's.
TEST_F(WorldQueries, ContactTestsAreBitIdenticalToSimpleBroadphase) {
    std::size_t contacts = 0, dbvt_extra = 0;
    for (int round = 0; round < kRounds; ++round) {
        place(worlds(), rng_);
        for (int body = 5; body < 5 + kBodies; ++body) {
            const std::vector<Bits> board = contacts_of(*board_, body);
            ASSERT_EQ(board, contacts_of(*simple_, body)) << "in btSimpleBroadphase's order; body " << body;
            const std::vector<Bits> mine = sorted(board), dbvt = sorted(contacts_of(*dbvt_, body));
            std::vector<Bits> extra;
            std::set_difference(dbvt.begin(), dbvt.end(), mine.begin(), mine.end(), std::back_inserter(extra));
            ASSERT_EQ(mine.size() + extra.size(), dbvt.size()) << "btDbvtBroadphase lost a contact of body " << body;
            btVector3 lo, hi;
            board_->bodies()[body]->getCollisionShape()->getAabb(board_->bodies()[body]->getWorldTransform(), lo, hi);
            for (const Bits& point : extra) {
                const auto other_index = static_cast<int32_t>(point[0]) == body ? point[1] : point[0];
                const btBroadphaseProxy* other = object_at(*board_, static_cast<int32_t>(other_index))->getBroadphaseHandle();
                EXPECT_FALSE(TestAabbAgainstAabb2(lo, hi, other->m_aabbMin, other->m_aabbMax)) << "body " << body;
            }
            contacts += board.size();
            dbvt_extra += extra.size();
        }
    }
    std::printf("%d contact tests: %zu points, %zu more on btDbvtBroadphase\n", kRounds * kBodies, contacts, dbvt_extra);
    EXPECT_GT(contacts, 20u);
}

}  // namespace
}  // namespace cdvp
