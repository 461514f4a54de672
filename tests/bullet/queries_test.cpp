// rayTest and aabbTest against brute force, and the broad phase's own
// bookkeeping (slots, capacity, faults) on a plain C++ link: no board needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "sw/baselines/brute_force.h"
#include "sw/bullet/board_broadphase.h"

namespace cdvp {
namespace {

// All pairs by brute force; fails the frame when told to.
class BruteLink : public BoardLink {
public:
    explicit BruteLink(uint32_t capacity) : capacity_(capacity) {}
    uint32_t capacity() const override { return capacity_; }
    const FrameResult& run(const std::vector<FloatBox>& boxes) override {
        if (fail_next) throw BoardFrameFault("board error status");
        result_.pairs.clear();
        brute_force_pairs(boxes, result_.pairs);
        return result_;
    }
    bool fail_next = false;

private:
    uint32_t capacity_;
    FrameResult result_;
};

struct Collect : btBroadphaseRayCallback {
    std::set<const btBroadphaseProxy*> hits;
    bool process(const btBroadphaseProxy* proxy) override { return hits.insert(proxy).second; }
};

std::vector<btBroadphaseProxy*> random_proxies(BoardBroadphase& broadphase, std::size_t n, std::mt19937& rng) {
    std::uniform_real_distribution<float> corner(-10, 10), size(0, 2);
    std::vector<btBroadphaseProxy*> proxies;
    for (std::size_t k = 0; k < n; ++k) {
        const btVector3 lo(corner(rng), corner(rng), corner(rng));
        const btVector3 hi = lo + btVector3(size(rng), size(rng), size(rng));
        proxies.push_back(broadphase.createProxy(lo, hi, BOX_SHAPE_PROXYTYPE, nullptr, 1, -1, nullptr));
    }
    return proxies;
}

// Reference in double: the segment's parameter interval inside each slab.
bool segment_hits(const btVector3& from, const btVector3& to, const btVector3& lo, const btVector3& hi) {
    double enter = 0, leave = 1;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = double(to[axis]) - from[axis];
        if (d == 0) {
            if (from[axis] < lo[axis] || from[axis] > hi[axis]) return false;
            continue;
        }
        const double a = (lo[axis] - double(from[axis])) / d, b = (hi[axis] - double(from[axis])) / d;
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    return enter <= leave;
}

TEST(BoardBroadphaseQueries, RayTestFindsExactlyTheBoxesTheSegmentMeets) {
    BruteLink link(300);
    BoardBroadphase broadphase(link);
    std::mt19937 rng(3);
    const auto proxies = random_proxies(broadphase, 300, rng);
    std::uniform_real_distribution<float> point(-12, 12);
    std::size_t total = 0;
    for (int ray = 0; ray < 200; ++ray) {
        const btVector3 from(point(rng), point(rng), point(rng));
        btVector3 to(point(rng), point(rng), point(rng));
        if (ray % 10 == 0) to[1] = from[1];  // some rays parallel to a slab
        Collect collect;
        collect.m_lambda_max = 1;
        broadphase.rayTest(from, to, collect);
        std::set<const btBroadphaseProxy*> expected;
        for (const btBroadphaseProxy* p : proxies) {
            if (segment_hits(from, to, p->m_aabbMin, p->m_aabbMax)) expected.insert(p);
        }
        ASSERT_EQ(collect.hits, expected) << "ray " << ray;
        total += expected.size();
    }
    EXPECT_GT(total, 100u);  // the rays do hit boxes
    // A ray that ends on a face touches it (closed boxes), and lambda_max shortens the ray.
    const btBroadphaseProxy* p = proxies[0];
    const btVector3 mid = (p->m_aabbMin + p->m_aabbMax) / 2;
    const btVector3 face(p->m_aabbMin[0], mid[1], mid[2]);
    Collect touching;
    touching.m_lambda_max = 1;
    broadphase.rayTest(face - btVector3(5, 0, 0), face, touching);
    EXPECT_EQ(touching.hits.count(p), 1u);
    Collect short_ray;
    short_ray.m_lambda_max = 0.5f;
    broadphase.rayTest(face - btVector3(5, 0, 0), face, short_ray);
    EXPECT_EQ(short_ray.hits.count(p), 0u);
}

struct CollectAabb : btBroadphaseAabbCallback {
    std::set<const btBroadphaseProxy*> hits;
    bool process(const btBroadphaseProxy* proxy) override { return hits.insert(proxy).second; }
};

TEST(BoardBroadphaseQueries, AabbTestFindsExactlyTheOverlappingBoxes) {
    BruteLink link(300);
    BoardBroadphase broadphase(link);
    std::mt19937 rng(4);
    const auto proxies = random_proxies(broadphase, 300, rng);
    std::uniform_real_distribution<float> corner(-12, 12), size(0, 6);
    for (int query = 0; query < 100; ++query) {
        const btVector3 lo(corner(rng), corner(rng), corner(rng));
        const btVector3 hi = lo + btVector3(size(rng), size(rng), size(rng));
        CollectAabb collect;
        broadphase.aabbTest(lo, hi, collect);
        std::set<const btBroadphaseProxy*> expected;
        for (const btBroadphaseProxy* p : proxies) {
            if (TestAabbAgainstAabb2(lo, hi, p->m_aabbMin, p->m_aabbMax)) expected.insert(p);
        }
        ASSERT_EQ(collect.hits, expected) << "query " << query;
    }
    btVector3 lo, hi;
    broadphase.getBroadphaseAabb(lo, hi);
    for (const btBroadphaseProxy* p : proxies) {
        EXPECT_TRUE(lo.x() <= p->m_aabbMin.x() && p->m_aabbMax.x() <= hi.x());
    }
}

TEST(BoardBroadphaseQueries, SlotsAreReusedLastFreedFirstAndBoardIndicesStayDense) {
    BruteLink link(4);
    BoardBroadphase broadphase(link);
    const btVector3 lo(0, 0, 0), hi(1, 1, 1);
    std::vector<btBroadphaseProxy*> p;
    for (int k = 0; k < 4; ++k) p.push_back(broadphase.createProxy(lo, hi, BOX_SHAPE_PROXYTYPE, nullptr, 1, -1, nullptr));
    EXPECT_EQ(p[0]->getUid(), 2);  // btSimpleBroadphase's ids: slot + 2
    EXPECT_THROW(broadphase.createProxy(lo, hi, BOX_SHAPE_PROXYTYPE, nullptr, 1, -1, nullptr), std::length_error);
    broadphase.calculateOverlappingPairs(nullptr);
    EXPECT_EQ(broadphase.getOverlappingPairCache()->getNumOverlappingPairs(), 6);
    broadphase.destroyProxy(p[1], nullptr);
    EXPECT_EQ(broadphase.getOverlappingPairCache()->getNumOverlappingPairs(), 3) << "p1's pairs go with it";
    EXPECT_EQ(broadphase.board_index(p[3]), 2u);
    broadphase.destroyProxy(p[2], nullptr);
    EXPECT_EQ(broadphase.createProxy(lo, hi, BOX_SHAPE_PROXYTYPE, nullptr, 1, -1, nullptr), p[2]);
    broadphase.calculateOverlappingPairs(nullptr);
    EXPECT_EQ(broadphase.last_frame().proxies, 3u);
    EXPECT_EQ(broadphase.getOverlappingPairCache()->getNumOverlappingPairs(), 3);
    broadphase.resetPool(nullptr);  // proxies live: nothing happens
    EXPECT_EQ(broadphase.proxy_count(), 3u);
}

TEST(BoardBroadphaseQueries, AFaultedFrameLeavesTheCacheAsItWas) {
    BruteLink link(10);
    BoardBroadphase broadphase(link);
    std::mt19937 rng(5);
    const auto proxies = random_proxies(broadphase, 10, rng);
    for (btBroadphaseProxy* p : proxies) broadphase.setAabb(p, btVector3(0, 0, 0), btVector3(1, 1, 1), nullptr);
    broadphase.calculateOverlappingPairs(nullptr);
    ASSERT_EQ(broadphase.getOverlappingPairCache()->getNumOverlappingPairs(), 45);
    broadphase.setAabb(proxies[0], btVector3(5, 5, 5), btVector3(6, 6, 6), nullptr);
    link.fail_next = true;
    EXPECT_THROW(broadphase.calculateOverlappingPairs(nullptr), BoardFrameFault);
    EXPECT_EQ(broadphase.getOverlappingPairCache()->getNumOverlappingPairs(), 45);
    link.fail_next = false;
    broadphase.calculateOverlappingPairs(nullptr);
    EXPECT_EQ(broadphase.getOverlappingPairCache()->getNumOverlappingPairs(), 36);
}

}  // namespace
}  // namespace cdvp
