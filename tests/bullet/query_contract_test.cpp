// The query contract of docs/bullet.md at the broad phase: the same proxies in
// the board's broad phase, btSimpleBroadphase and btDbvtBroadphase, and rays,
// swept boxes and AABB queries set up as Bullet's world sets them up. No board
// is elaborated: queries run on the host (HostPairsLink only sizes the slots).
#include <gtest/gtest.h>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/BroadphaseCollision/btSimpleBroadphase.h>
#include <LinearMath/btAabbUtil2.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sw/bullet/board_broadphase.h"

namespace cdvp {
namespace {

constexpr int kProxies = 300;

int id_of(const btBroadphaseProxy* proxy) { return static_cast<int>(reinterpret_cast<intptr_t>(proxy->m_clientObject)) - 1; }

// A ray callback set up as btCollisionWorld's btSingleRayCallback and
// btSingleSweepCallback set theirs: the direction normalized, its inverse
// (BT_LARGE_FLOAT where a component is 0) and signs, m_lambda_max the length.
// It records the proxies it is handed, in order.
struct BulletStyleRay : btBroadphaseRayCallback {
    BulletStyleRay(const btVector3& from, const btVector3& to) {
        const btVector3 segment = to - from;
        const btVector3 direction = segment.fuzzyZero() ? btVector3(0, 0, 0) : segment.normalized();
        for (int axis = 0; axis < 3; ++axis) {
            m_rayDirectionInverse[axis] = direction[axis] == 0 ? btScalar(BT_LARGE_FLOAT) : 1 / direction[axis];
            m_signs[axis] = m_rayDirectionInverse[axis] < 0;
        }
        m_lambda_max = direction.dot(segment);
    }
    bool process(const btBroadphaseProxy* proxy) override {
        order.push_back(id_of(proxy));
        return true;
    }
    std::vector<int> order;
};

struct RecordingAabb : btBroadphaseAabbCallback {
    bool process(const btBroadphaseProxy* proxy) override {
        order.push_back(id_of(proxy));
        return true;
    }
    std::vector<int> order;
};

// The same proxies, created in the same order, in the three broad phases.
class ThreeBroadphases {
public:
    ThreeBroadphases() : link_(kProxies), board_(link_), simple_(2 * kProxies) {}
    ThreeBroadphases(const ThreeBroadphases&) = delete;
    ThreeBroadphases& operator=(const ThreeBroadphases&) = delete;
    // A broad phase frees only the proxies destroyed through it (btDbvtBroadphase
    // allocates each one), as a world removes its objects before it goes.
    ~ThreeBroadphases() {
        for (auto& [broadphase, proxies] : proxies_) {
            for (btBroadphaseProxy* proxy : proxies) broadphase->destroyProxy(proxy, nullptr);
        }
    }

    void create(const btVector3& lo, const btVector3& hi) {
        void* client = reinterpret_cast<void*>(static_cast<intptr_t>(boxes_.size()) + 1);  // btSimpleBroadphase skips null
        for (btBroadphaseInterface* broadphase : all()) {
            proxies_[broadphase].push_back(broadphase->createProxy(lo, hi, BOX_SHAPE_PROXYTYPE, client, 1, -1, nullptr));
        }
        boxes_.push_back({lo, hi});
    }
    void move(int id, const btVector3& lo, const btVector3& hi) {
        for (btBroadphaseInterface* broadphase : all()) broadphase->setAabb(proxies_[broadphase][id], lo, hi, nullptr);
        boxes_[id] = {lo, hi};
    }
    std::vector<btBroadphaseInterface*> all() { return {&board_, &simple_, &dbvt_}; }
    BoardBroadphase& board() { return board_; }
    btSimpleBroadphase& simple() { return simple_; }
    btDbvtBroadphase& dbvt() { return dbvt_; }
    const std::vector<std::pair<btVector3, btVector3>>& boxes() const { return boxes_; }

private:
    HostPairsLink link_;
    BoardBroadphase board_;
    btSimpleBroadphase simple_;
    btDbvtBroadphase dbvt_;
    std::map<btBroadphaseInterface*, std::vector<btBroadphaseProxy*>> proxies_;
    std::vector<std::pair<btVector3, btVector3>> boxes_;
};

void fill_random(ThreeBroadphases& broadphases, std::mt19937& rng) {
    std::uniform_real_distribution<float> corner(-10, 10), size(0.05f, 2);
    for (int k = 0; k < kProxies; ++k) {
        const btVector3 lo(corner(rng), corner(rng), corner(rng));
        broadphases.create(lo, lo + btVector3(size(rng), size(rng), size(rng)));
    }
}

// Reference in double: the parameter interval s in [0, 1] along from -> to
// where the segment is inside the closed box [lo, hi] grown by the swept box
// (lo - sweep_max, hi - sweep_min); empty when enter > leave.
struct Interval {
    double enter, leave;
    bool meets() const { return enter <= leave; }
};
Interval segment_interval(const btVector3& from, const btVector3& to, btVector3 lo, btVector3 hi,
                          const btVector3& sweep_min, const btVector3& sweep_max) {
    double enter = 0, leave = 1;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = double(lo[axis]) - sweep_max[axis], high = double(hi[axis]) - sweep_min[axis];
        const double d = double(to[axis]) - from[axis];
        if (d == 0) {
            if (from[axis] < low || from[axis] > high) return {1, 0};
            continue;
        }
        const double a = (low - from[axis]) / d, b = (high - from[axis]) / d;
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    return {enter, leave};
}

bool ascending(const std::vector<int>& order) { return std::is_sorted(order.begin(), order.end()) &&
                                                        std::adjacent_find(order.begin(), order.end()) == order.end(); }
std::set<int> as_set(const std::vector<int>& order) { return {order.begin(), order.end()}; }

struct RayCounts {
    std::size_t hits = 0;          // boxes reported over all rays
    std::size_t past_length = 0;   // boxes first met beyond s = length on rays shorter than a unit
    std::size_t beyond_end = 0;    // boxes the line meets past the segment's end, not reported
    void print(const char* what) const {
        std::printf("%s: %zu boxes met, %zu of them past s = length, %zu beyond the end left out\n", what, hits,
                    past_length, beyond_end);
    }
};

// One ray (or swept box) through the three broad phases: the board reports
// exactly the boxes the segment meets, in slot order (btSimpleBroadphase's
// handle order, which reports every proxy), and none btDbvtBroadphase leaves out.
void check_ray(ThreeBroadphases& broadphases, const btVector3& from, const btVector3& to, const btVector3& sweep_min,
               const btVector3& sweep_max, RayCounts& counts) {
    BulletStyleRay board(from, to), simple(from, to), dbvt(from, to);
    broadphases.board().rayTest(from, to, board, sweep_min, sweep_max);
    broadphases.simple().rayTest(from, to, simple, sweep_min, sweep_max);
    broadphases.dbvt().rayTest(from, to, dbvt, sweep_min, sweep_max);
    std::set<int> expected;
    const double length = (to - from).length();
    for (int id = 0; id < static_cast<int>(broadphases.boxes().size()); ++id) {
        const auto& [lo, hi] = broadphases.boxes()[id];
        const Interval inside = segment_interval(from, to, lo, hi, sweep_min, sweep_max);
        if (inside.meets()) {
            expected.insert(id);
            if (length < 1 && inside.enter > length) ++counts.past_length;
        } else if (segment_interval(from, from + (to - from) * 40, lo, hi, sweep_min, sweep_max).meets()) {
            ++counts.beyond_end;
        }
    }
    ASSERT_EQ(as_set(board.order), expected) << "ray from " << from.x() << "," << from.y() << "," << from.z()
                                             << " of length " << length;
    ASSERT_TRUE(ascending(board.order)) << "the board reports in slot order";
    ASSERT_EQ(simple.order.size(), broadphases.boxes().size()) << "btSimpleBroadphase reports every proxy";
    ASSERT_TRUE(ascending(simple.order));
    const std::set<int> dbvt_set = as_set(dbvt.order);
    ASSERT_TRUE(std::includes(dbvt_set.begin(), dbvt_set.end(), expected.begin(), expected.end()))
        << "btDbvtBroadphase reports every box the segment meets";
    counts.hits += expected.size();
}

btVector3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    btVector3 v(normal(rng), normal(rng), normal(rng));
    return v.fuzzyZero() ? btVector3(1, 0, 0) : v.normalized();
}

// Rays aimed at a random box from just outside it (so that short ones reach
// it), of a length drawn from [min_length, max_length]; every tenth parallel to a slab.
void check_rays(ThreeBroadphases& broadphases, std::mt19937& rng, float min_length, float max_length,
                const btVector3& sweep_min, const btVector3& sweep_max, RayCounts& counts) {
    std::uniform_int_distribution<int> box(0, kProxies - 1), axis(0, 2);
    std::uniform_real_distribution<float> unit(0, 1), gap(0, 0.5f), length(min_length, max_length);
    for (int ray = 0; ray < 300; ++ray) {
        // From beyond one face of the box, towards a point inside it.
        const auto& [lo, hi] = broadphases.boxes()[box(rng)];
        const btVector3 target = lo + (hi - lo) * btVector3(unit(rng), unit(rng), unit(rng));
        btVector3 from = target;
        const int face = axis(rng);
        from[face] = unit(rng) < 0.5f ? lo[face] - gap(rng) : hi[face] + gap(rng);
        btVector3 direction = (target - from).normalized() + random_unit(rng) * 0.3f;
        if (ray % 10 == 0) direction[ray % 3] = 0;
        const btVector3 to = from + direction.normalized() * length(rng);
        check_ray(broadphases, from, to, sweep_min, sweep_max, counts);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

// 300 rays (or swept boxes) of each length range through 300 random boxes.
RayCounts run_rays(unsigned seed, std::initializer_list<std::pair<float, float>> lengths, const btVector3& sweep_min,
                   const btVector3& sweep_max, const char* what) {
    ThreeBroadphases broadphases;
    std::mt19937 rng(seed);
    fill_random(broadphases, rng);
    RayCounts counts;
    for (const auto& [shortest, longest] : lengths) {
        check_rays(broadphases, rng, shortest, longest, sweep_min, sweep_max, counts);
    }
    counts.print(what);
    return counts;
}

const btVector3 kNoSweep(0, 0, 0);

TEST(BoardQueryContract, RaysShorterThanAUnitMeetEveryBoxOfTheirSegment) {
    const RayCounts counts = run_rays(21, {{0.05f, 1}}, kNoSweep, kNoSweep, "300 rays of 0.05 to 1");
    EXPECT_GT(counts.hits, 100u);
    // The boxes a ray of length L < 1 meets past s = L (of its segment): a
    // broad phase reading m_lambda_max as a fraction of the segment misses them.
    EXPECT_GT(counts.past_length, 20u);
}

TEST(BoardQueryContract, LongRaysStopAtTheirEnd) {
    const RayCounts counts = run_rays(22, {{1, 30}}, kNoSweep, kNoSweep, "300 rays of 1 to 30");
    EXPECT_GT(counts.hits, 200u);
    EXPECT_GT(counts.beyond_end, 15u) << "boxes past the rays' ends, which must not be reported";
}

// convexSweepTest's query: the origin's segment against boxes grown by the
// cast shape's box (symmetric for a sphere, any box for a turned shape).
TEST(BoardQueryContract, SweptBoxesShortAndLongMeetTheGrownBoxes) {
    const RayCounts sphere = run_rays(23, {{0.05f, 1}, {1, 30}}, btVector3(-0.3f, -0.3f, -0.3f),
                                      btVector3(0.3f, 0.3f, 0.3f), "600 sweeps of a sphere's box, 0.05 to 30");
    const RayCounts turned = run_rays(24, {{0.05f, 1}, {1, 30}}, btVector3(-0.2f, -0.6f, -0.1f),
                                      btVector3(0.4f, 0.1f, 0.3f), "600 sweeps of a turned shape's box, 0.05 to 30");
    for (const RayCounts& counts : {sphere, turned}) {
        EXPECT_GT(counts.hits, 500u);
        EXPECT_GT(counts.past_length, 10u);
    }
}

// A callback that keeps only the nearest box and shortens m_lambda_max to its
// entry: what it is handed must be reached within the length it had then, and
// its answer, the nearest box, must be the same on every broad phase.
struct NearestBox : BulletStyleRay {
    NearestBox(const btVector3& from, const btVector3& to, const btVector3& sweep_min, const btVector3& sweep_max)
        : BulletStyleRay(from, to), from_(from), sweep_min_(sweep_min), sweep_max_(sweep_max) {}
    bool process(const btBroadphaseProxy* proxy) override {
        BulletStyleRay::process(proxy);
        btScalar entry = 0;
        const btVector3 bounds[2] = {proxy->m_aabbMin - sweep_max_, proxy->m_aabbMax - sweep_min_};
        const bool reached = btRayAabb2(from_, m_rayDirectionInverse, m_signs, bounds, entry, 0, m_lambda_max);
        reached_when_handed.push_back(reached);
        if (reached) {
            nearest = id_of(proxy);
            m_lambda_max = entry;
        }
        return true;
    }
    btVector3 from_, sweep_min_, sweep_max_;
    std::vector<bool> reached_when_handed;
    int nearest = -1;
};

TEST(BoardQueryContract, ACallbackThatShortensLambdaMaxClipsTheRestOfTheQuery) {
    ThreeBroadphases broadphases;
    std::mt19937 rng(24);
    fill_random(broadphases, rng);
    std::uniform_real_distribution<float> point(-12, 12);
    std::size_t handed_clipping = 0, handed_full = 0, with_hit = 0;
    for (int ray = 0; ray < 200; ++ray) {
        const btVector3 sweep = ray % 2 ? btVector3(0.2f, 0.2f, 0.2f) : btVector3(0, 0, 0);
        // From outside every (grown) box, so that the nearest box has one entry.
        btVector3 from;
        do {
            from = btVector3(point(rng), point(rng), point(rng));
        } while (std::any_of(broadphases.boxes().begin(), broadphases.boxes().end(), [&](const auto& box) {
            return TestPointAgainstAabb2(box.first - sweep, box.second + sweep, from);
        }));
        const btVector3 to(point(rng), point(rng), point(rng));
        NearestBox board(from, to, -sweep, sweep), simple(from, to, -sweep, sweep), dbvt(from, to, -sweep, sweep);
        broadphases.board().rayTest(from, to, board, -sweep, sweep);
        broadphases.simple().rayTest(from, to, simple, -sweep, sweep);
        broadphases.dbvt().rayTest(from, to, dbvt, -sweep, sweep);
        // Each proxy handed over was still within reach when it was handed.
        ASSERT_TRUE(std::all_of(board.reached_when_handed.begin(), board.reached_when_handed.end(),
                                [](bool reached) { return reached; }))
            << "ray " << ray;
        ASSERT_TRUE(ascending(board.order)) << "ray " << ray;
        ASSERT_EQ(board.nearest, simple.nearest) << "ray " << ray;
        ASSERT_EQ(board.nearest, dbvt.nearest) << "ray " << ray;
        BulletStyleRay full(from, to);
        broadphases.board().rayTest(from, to, full, -sweep, sweep);
        handed_clipping += board.order.size();
        handed_full += full.order.size();
        with_hit += board.nearest >= 0 ? 1 : 0;
    }
    std::printf("200 rays: %zu with a nearest box; %zu boxes handed to the shortening callback, %zu to a plain one\n",
                with_hit, handed_clipping, handed_full);
    EXPECT_GT(with_hit, 100u);
    EXPECT_LT(handed_clipping, handed_full) << "a shortened ray should skip the boxes behind its nearest";
}

// btSimpleBroadphase's test in its order; btDbvtBroadphase's fresh leaves are
// the boxes themselves, and once boxes move its leaves only grow.
TEST(BoardQueryContract, AabbTestReportsSimpleBroadphasesBoxesInItsOrder) {
    ThreeBroadphases broadphases;
    std::mt19937 rng(25);
    fill_random(broadphases, rng);
    std::uniform_real_distribution<float> corner(-12, 12), size(0, 6), step(-0.3f, 0.3f);
    std::size_t reported = 0;
    for (int round = 0; round < 2; ++round) {
        for (int query = 0; query < 100; ++query) {
            const btVector3 lo(corner(rng), corner(rng), corner(rng));
            const btVector3 hi = lo + btVector3(size(rng), size(rng), size(rng));
            RecordingAabb board, simple, dbvt;
            broadphases.board().aabbTest(lo, hi, board);
            broadphases.simple().aabbTest(lo, hi, simple);
            broadphases.dbvt().aabbTest(lo, hi, dbvt);
            ASSERT_EQ(board.order, simple.order) << "round " << round << " query " << query;
            const std::set<int> board_set = as_set(board.order), dbvt_set = as_set(dbvt.order);
            if (round == 0) {
                ASSERT_EQ(board_set, dbvt_set) << "query " << query;
            } else {
                ASSERT_TRUE(std::includes(dbvt_set.begin(), dbvt_set.end(), board_set.begin(), board_set.end()));
            }
            reported += board.order.size();
        }
        for (int id = 0; id < kProxies; ++id) {  // every box moves a little
            const btVector3 shift(step(rng), step(rng), step(rng));
            const auto [lo, hi] = broadphases.boxes()[id];
            broadphases.move(id, lo + shift, hi + shift);
        }
    }
    EXPECT_GT(reported, 200u);
    // A query touching a box's face reports it (closed boxes).
    const auto& [lo, hi] = broadphases.boxes()[0];
    RecordingAabb touching;
    broadphases.board().aabbTest(hi, hi + btVector3(1, 1, 1), touching);
    EXPECT_EQ(as_set(touching.order).count(0), 1u);
}

}  // namespace
}  // namespace cdvp
