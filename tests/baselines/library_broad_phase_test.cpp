// The baselines that wrap FCL's managers and ODE's spaces: that the pairs come
// from the library and its update, that what it cannot hold stays out, and
// that hostile boxes (NaN, inverted, infinite, FLT_MAX, denormal, -0,
// identical, touching) give the exact pairs, for these and every baseline.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/brute_force.h"
#include "sw/baselines/library_broad_phase.h"
#include "tests/baselines/exact_pairs.h"
#include "tests/baselines/scenes.h"

namespace cdvp {
namespace {

using test::Boxes;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenormal = std::numeric_limits<float>::denorm_min();

const std::vector<std::string> kLibraryNames = {"fcl_tree", "fcl_sap",  "fcl_interval", "fcl_hash",
                                                "ode_hash", "ode_quadtree", "ode_sap"};

FloatBox box(float x0, float y0, float z0, float x1, float y1, float z1) { return {{x0, y0, z0}, {x1, y1, z1}}; }

const LibraryCounts& counts(const BroadPhase& phase) {
    const auto* library = dynamic_cast<const LibraryBroadPhase*>(&phase);
    if (library == nullptr) throw std::logic_error(phase.name() + " wraps no library");
    return library->counts();
}

// Random company (grid coordinates 0 .. ~17) and, from index 200, boxes
// hostile to one library or another. The indices of the hostile ones are
// named so that later frames can change them.
constexpr std::size_t kCompany = 200;
enum Hostile : std::size_t {
    kNanLow = kCompany, kAllNan, kNanHigh, kInvertedX, kInvertedAll, kEverything, kRod, kFltMax, kMaxPoint,
    kDenormalBox, kDenormalNeighbour, kMinusZero, kPlusZero, kCopy1, kCopy2, kCopy3, kTouchA, kTouchB, kFarPoint,
    kFarBox, kWide, kCount
};

Boxes hostile_scene() {
    Boxes boxes = test::random_boxes(kCompany, 7);
    boxes.resize(kCount);
    boxes[kNanLow] = box(kNan, 1, 1, 2, 2, 2);  // a NaN bound: overlaps nothing
    boxes[kAllNan] = box(kNan, kNan, kNan, kNan, kNan, kNan);
    boxes[kNanHigh] = box(1, 1, 1, 2, kNan, 2);
    boxes[kInvertedX] = box(3, 0, 0, 2, 20, 20);  // min > max on x: the test still pairs it
    boxes[kInvertedAll] = box(5, 5, 5, 4, 4, 4);
    boxes[kEverything] = box(-kInf, -kInf, -kInf, kInf, kInf, kInf);
    boxes[kRod] = box(-kInf, -0.5f, -0.5f, 0, 0, 0);  // ends at x = 0, on the +0 point
    boxes[kFltMax] = box(-FLT_MAX, -FLT_MAX, -FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX);
    boxes[kMaxPoint] = box(FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX);
    boxes[kDenormalBox] = box(-kDenormal, -kDenormal, -kDenormal, kDenormal, kDenormal, kDenormal);
    boxes[kDenormalNeighbour] = box(kDenormal, kDenormal, kDenormal, 3 * kDenormal, 3 * kDenormal, 3 * kDenormal);
    boxes[kMinusZero] = box(-1, -1, -1, -0.0f, -0.0f, -0.0f);  // touches +0
    boxes[kPlusZero] = box(0.0f, 0.0f, 0.0f, 0, 0, 0);         // a point
    boxes[kCopy1] = boxes[kCopy2] = boxes[kCopy3] = box(30, 30, 30, 31, 31, 31);
    boxes[kTouchA] = box(40, 40, 40, 41, 41, 41);
    boxes[kTouchB] = box(41, 40, 40, 42, 41, 41);  // face to face with kTouchA
    boxes[kFarPoint] = box(1e30f, 1e30f, 1e30f, 1e30f, 1e30f, 1e30f);
    boxes[kFarBox] = box(1e30f, 1e30f, 1e30f, 2e30f, 2e30f, 2e30f);  // holds kFarPoint on its corner
    boxes[kWide] = box(-500, 2, 2, 500, 3, 3);  // across every cell of a hash
    return boxes;
}

bool has(const PairList& pairs, std::size_t a, std::size_t b) {
    return std::binary_search(pairs.begin(), pairs.end(), IndexPair{uint32_t(a), uint32_t(b)});
}

class HostileBoxes : public ::testing::TestWithParam<std::string> {};

TEST_P(HostileBoxes, GiveTheExactPairs) {
    auto phase = make_broad_phase(GetParam());
    const Boxes boxes = hostile_scene();
    const PairList want = test::expect_exact(*phase, boxes, "the hostile scene");
    // The scene has what it claims (the reference is the judge of each case).
    EXPECT_TRUE(has(want, kMinusZero, kPlusZero));
    EXPECT_TRUE(has(want, kFltMax, kMaxPoint));
    EXPECT_TRUE(has(want, kEverything, kMaxPoint));
    EXPECT_TRUE(has(want, kDenormalBox, kDenormalNeighbour));
    EXPECT_TRUE(has(want, kCopy1, kCopy2) && has(want, kCopy1, kCopy3) && has(want, kCopy2, kCopy3));
    EXPECT_TRUE(has(want, kTouchA, kTouchB));
    EXPECT_TRUE(has(want, kFarPoint, kFarBox));
    EXPECT_TRUE(has(want, kRod, kPlusZero));
    EXPECT_TRUE(has(want, kInvertedX, kWide));
    for (const IndexPair& p : want) {
        EXPECT_FALSE(p.first == kNanLow || p.second == kNanLow || p.first == kAllNan || p.second == kAllNan);
    }
}

// The same boxes moved: hostile ones turn ordinary and ordinary ones hostile,
// boxes grow and shrink, frame after frame (the incremental paths).
TEST_P(HostileBoxes, TurnOrdinaryAndBackAsTheyMove) {
    auto phase = make_broad_phase(GetParam());
    Boxes boxes = hostile_scene();
    test::expect_exact(*phase, boxes, "frame 0");
    for (int frame = 1; frame <= 4; ++frame) {
        const bool odd = frame % 2 == 1;
        boxes[kNanLow] = odd ? box(1, 1, 1, 2, 2, 2) : box(kNan, 1, 1, 2, 2, 2);
        boxes[kInvertedAll] = odd ? box(4, 4, 4, 5, 5, 5) : box(5, 5, 5, 4, 4, 4);
        boxes[3] = odd ? box(3, 3, kNan, 4, 4, 4) : box(3, 3, 3, 4, 4, 4);
        boxes[4] = odd ? box(6, 6, 6, 5, 7, 7) : box(5, 6, 6, 6, 7, 7);
        boxes[kEverything] = odd ? box(0, 0, 0, 8, 8, 8) : box(-kInf, -kInf, -kInf, kInf, kInf, kInf);
        boxes[kWide] = odd ? box(2, 2, 2, 3, 3, 3) : box(-500, 2, 2, 500, 3, 3);
        for (std::size_t i = 10; i < 60; ++i) {  // grow on both sides, then shrink back
            const float d = odd ? 0.5f : -0.5f;
            for (int axis = 0; axis < 3; ++axis) {
                boxes[i].min[axis] -= d;
                boxes[i].max[axis] += d;
            }
        }
        test::expect_exact(*phase, boxes, "frame " + std::to_string(frame));
    }
}

TEST_P(HostileBoxes, KeepTheirPairBudgetWithBoxesOutsideTheLibrary) {
    auto phase = make_broad_phase(GetParam());
    const Boxes boxes = hostile_scene();
    const std::size_t all = reference_pairs(boxes).size();
    PairList pairs;
    phase->set_pair_budget(PairBudget(all));
    phase->find_pairs(boxes, pairs);
    EXPECT_EQ(pairs.size(), all);
    phase->set_pair_budget(PairBudget(all - 1));
    EXPECT_THROW(phase->find_pairs(boxes, pairs), PairBudgetExceeded);
    EXPECT_LE(pairs.size(), all - 1);
}

// Every baseline but dbvt: Bullet's btDbvtBroadphase misses pairs of a box
// inverted on an axis (min > max), which the exact test still pairs.
std::vector<std::string> hostile_proof_names() {
    std::vector<std::string> names = broad_phase_names();
    names.erase(std::find(names.begin(), names.end(), "dbvt"));
    return names;
}

INSTANTIATE_TEST_SUITE_P(Baselines, HostileBoxes, ::testing::ValuesIn(hostile_proof_names()),
                         [](const auto& info) { return info.param; });

class LibraryBaseline : public ::testing::TestWithParam<std::string> {};

// The pairs come from the library's callback, and a moved scene goes through
// its update, not a new build, and changes the pairs.
TEST_P(LibraryBaseline, FindsThePairsThroughTheLibraryAndItsUpdate) {
    auto phase = make_broad_phase(GetParam());
    EXPECT_EQ(phase->name(), GetParam());
    const auto frames = test::moving_frames(300, 6, 17);
    const PairList first = test::expect_exact(*phase, frames[0], "frame 0");
    ASSERT_GT(first.size(), 50u);
    EXPECT_EQ(counts(*phase).builds, 1u);
    EXPECT_EQ(counts(*phase).updates, 0u);
    EXPECT_EQ(counts(*phase).held, frames[0].size());
    EXPECT_GE(counts(*phase).candidates, first.size());
    const PairList last = test::expect_exact(*phase, frames[5], "frame 5, after 4 more");
    EXPECT_NE(first, last) << "the motion should change the pairs";
    EXPECT_EQ(counts(*phase).builds, 1u) << "a move of the same boxes is an update";
    EXPECT_EQ(counts(*phase).updates, 1u);
    EXPECT_GE(counts(*phase).candidates, last.size());
    test::expect_exact(*phase, test::random_boxes(301, 3), "another count");
    EXPECT_EQ(counts(*phase).builds, 2u);
}

// What each library is handed of the hostile scene: never NaN or inverted
// boxes; infinite ones where it takes them; not what a hash cannot index.
TEST_P(LibraryBaseline, HoldsWhatItCanRepresent) {
    auto phase = make_broad_phase(GetParam());
    PairList pairs;
    phase->find_pairs(hostile_scene(), pairs);
    std::size_t out = 5;  // three with a NaN bound, two inverted
    if (GetParam() == "fcl_hash") out += 5;  // the infinite two, and FLT_MAX, the far box, the wide one: over 8 cells
    if (GetParam() == "ode_hash") out += 4;  // FLT_MAX, the FLT_MAX point, the far point and box: beyond int cells
    EXPECT_EQ(counts(*phase).held, kCount - out);
}

INSTANTIATE_TEST_SUITE_P(Libraries, LibraryBaseline, ::testing::ValuesIn(kLibraryNames),
                         [](const auto& info) { return info.param; });

// A hash reports the boxes sharing its cells, ODE's sweep every pair with an
// infinite geom: more than overlap, and the exact test drops the rest.
TEST(LibraryBaselines, TheExactTestDropsALibrarysExtraCandidates) {
    auto hash = make_broad_phase("fcl_hash");
    const PairList want = test::expect_exact(*hash, test::random_boxes(700, 5), "random boxes");
    EXPECT_GT(counts(*hash).candidates, want.size());
    auto sap = make_broad_phase("ode_sap");
    const PairList infinite = test::expect_exact(*sap, test::infinite_scene(), "the infinite scene");
    EXPECT_GT(counts(*sap).candidates, infinite.size());
}

// FCL's SaP takes only moves that carry both ends of an axis the same way: a
// box that grows, shrinks or keeps one end gets there in two of them,
// through its update, and the pairs stay exact.
TEST(LibraryBaselines, FclSapTakesBoxesThatGrowOrShrinkThroughItsUpdate) {
    auto sap = make_broad_phase("fcl_sap");
    Boxes boxes = test::random_boxes(400, 9);
    test::expect_exact(*sap, boxes, "frame 0");
    for (FloatBox& b : boxes) {
        b.min[0] += 0.125f;
        b.max[0] += 0.125f;
    }
    test::expect_exact(*sap, boxes, "all moved along x");
    EXPECT_EQ(counts(*sap).builds, 1u);
    for (std::size_t i = 0; i < 100; ++i) boxes[i].max[1] += 3;  // grow upwards only
    test::expect_exact(*sap, boxes, "100 boxes grown");
    for (std::size_t i = 50; i < 150; ++i) {  // shrink, or keep the lower end
        boxes[i].min[2] += 0.125f;
        boxes[i].max[2] -= i % 2 == 0 ? 0.125f : 0.0f;
        boxes[i].max[2] = std::max(boxes[i].max[2], boxes[i].min[2]);
    }
    test::expect_exact(*sap, boxes, "100 boxes shrunk");
    EXPECT_EQ(counts(*sap).builds, 1u);
    EXPECT_EQ(counts(*sap).updates, 3u);
}

TEST(LibraryBaselines, OdeHashRefusesMoreBoxesThanItsTestedMatrixIndexes) {
    auto hash = make_broad_phase("ode_hash");
    PairList pairs;
    const Boxes many(131001, box(0, 0, 0, 1, 1, 1));
    try {
        hash->find_pairs(many, pairs);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "ode_hash: ODE's hash space holds at most 131000 boxes (its tested-pair matrix "
                                   "is indexed by an int); got 131001");
    }
    test::expect_exact(*hash, test::random_boxes(50, 1), "a small scene after");
}

}  // namespace
}  // namespace cdvp
