// aabbTest against brute force, and the broad phase's own bookkeeping (slots,
// capacity, faults) on a plain C++ link: no board needed. Rays and swept boxes
// against Bullet's broad phases: query_contract_test.cpp.
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
