// The board model (the seed's all-pairs board and the grid board) and the
// all-pairs baselines against CGAL on the original doubles: every CGAL pair is
// found, and an extra pair only where the double-to-float conversion widens a
// box enough to bridge the gap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "models/board/board_core.h"
#include "sw/baselines/broad_phase.h"
#include "sw/scene/conversion.h"
#include "sw/scene/trace_csv.h"
#include "tests/oracle/cgal_oracle.h"
#include "tests/oracle/oracle_scenes.h"
#include "tests/support/core_driver.h"

namespace cdvp::oracle {
namespace {

constexpr float kFloatInf = std::numeric_limits<float>::infinity();

bool intervals_meet(double lo_a, double hi_a, double lo_b, double hi_b) { return lo_a <= hi_b && lo_b <= hi_a; }

// f is the smallest float >= v (an upper bound rounded outward, no further).
bool tight_upper(float f, double v) {
    return static_cast<double>(f) >= v && (f == -kFloatInf || static_cast<double>(std::nextafterf(f, -kFloatInf)) < v);
}
// f is the largest float <= v.
bool tight_lower(float f, double v) {
    return static_cast<double>(f) <= v && (f == kFloatInf || static_cast<double>(std::nextafterf(f, kFloatInf)) > v);
}

std::string describe(const Box& b) {
    std::ostringstream out;
    out.precision(17);
    out << "[" << b.min[0] << "," << b.max[0] << "]x[" << b.min[1] << "," << b.max[1] << "]x[" << b.min[2] << ","
        << b.max[2] << "]";
    return out.str();
}

// Explains why an extra pair (i, j) is not explained by conversion, or "".
std::string unexplained(const Box& a, const Box& b, const FloatBox& fa, const FloatBox& fb) {
    bool disjoint = false;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(fa.min[axis] <= fb.max[axis] && fb.min[axis] <= fa.max[axis])) return "float boxes are disjoint";
        if (intervals_meet(a.min[axis], a.max[axis], b.min[axis], b.max[axis])) continue;
        disjoint = true;
        // The double gap on this axis is bridged: the bounds facing each
        // other must be the nearest floats outward, not wider.
        const bool a_below = a.max[axis] < b.min[axis];
        const Box& low = a_below ? a : b;
        const Box& high = a_below ? b : a;
        const FloatBox& flow = a_below ? fa : fb;
        const FloatBox& fhigh = a_below ? fb : fa;
        if (!tight_upper(flow.max[axis], low.max[axis]) || !tight_lower(fhigh.min[axis], high.min[axis])) {
            return "axis " + std::to_string(axis) + " widened by more than the rounding";
        }
    }
    return disjoint ? "" : "the double boxes overlap, yet CGAL did not report them";
}

// Checks 'found' against the oracle; returns how many extra pairs it holds.
std::size_t expect_oracle_subset(const std::string& who, const std::vector<Box>& boxes,
                                 const std::vector<FloatBox>& float_boxes, const PairList& oracle,
                                 const PairList& found) {
    EXPECT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end()) << who << ": duplicate pairs";
    PairList missing;
    std::set_difference(oracle.begin(), oracle.end(), found.begin(), found.end(), std::back_inserter(missing));
    EXPECT_TRUE(missing.empty()) << who << " lost " << missing.size() << " pairs, first (" << missing[0].first
                                 << ", " << missing[0].second << ")";
    PairList extra;
    std::set_difference(found.begin(), found.end(), oracle.begin(), oracle.end(), std::back_inserter(extra));
    for (const IndexPair& p : extra) {
        const std::string why = unexplained(boxes[p.first], boxes[p.second], float_boxes[p.first],
                                            float_boxes[p.second]);
        EXPECT_EQ("", why) << who << " extra pair (" << p.first << ", " << p.second
                           << "): " << describe(boxes[p.first]) << " " << describe(boxes[p.second]);
    }
    return extra.size();
}

struct Outcome {
    std::size_t oracle_pairs = 0;
    std::size_t extra_pairs = 0;
    PairList board;
};

// Runs CGAL, the board model (no kernel) and the soa and brute baselines on
// one scene and checks each against the oracle.
Outcome check_scene(const std::vector<Box>& boxes, uint32_t m = 16) {
    const PairList oracle = cgal_pairs(boxes);
    EXPECT_TRUE(std::adjacent_find(oracle.begin(), oracle.end()) == oracle.end()) << "CGAL reported a pair twice";
    const std::vector<FloatBox> float_boxes = to_float_boxes(boxes);

    BoardConfig config;
    config.m = m;
    BoardCore core(config, static_cast<uint32_t>(boxes.size()));
    const PairList board = sorted(testing::run_core(core, float_boxes).pairs);
    Outcome outcome{oracle.size(), expect_oracle_subset("board", boxes, float_boxes, oracle, board), board};
    // The grid board (docs/grid_board.md) finds the all-pairs board's pairs exactly.
    config.algorithm = BoardAlgorithm::kGrid;
    BoardCore grid(config, static_cast<uint32_t>(boxes.size()), Fidelity::kFast);
    EXPECT_EQ(board, sorted(testing::run_core(grid, float_boxes).pairs)) << "the grid board and the board differ";
    for (const char* name : {"soa", "brute"}) {
        PairList found;
        make_broad_phase(name)->find_pairs(float_boxes, found);
        found = sorted(std::move(found));
        expect_oracle_subset(name, boxes, float_boxes, oracle, found);
        EXPECT_EQ(board, found) << name << " and the board differ";
    }
    return outcome;
}

TEST(Oracle, RandomFloatExactSceneHasNoExtraPairs) {
    const Outcome outcome = check_scene(random_scene(4000, 40.0, 4.0, true, 11));
    EXPECT_GT(outcome.oracle_pairs, 1000u);
    EXPECT_EQ(0u, outcome.extra_pairs);
}

TEST(Oracle, RandomDoubleScene) {
    const Outcome outcome = check_scene(random_scene(4000, 40.0, 4.0, false, 12), 7);
    EXPECT_GT(outcome.oracle_pairs, 1000u);
}

TEST(Oracle, ClusteredScene) {
    const Outcome outcome = check_scene(clustered_scene(4000, 12, 3.0, 2.0, 13));
    EXPECT_GT(outcome.oracle_pairs, 3000u);
}

// Near 1e7 floats are 1 apart and near 1e8 8 apart: many boxes a fraction
// of a unit apart become touching in float. Each such pair must be an extra
// explained by the rounding, and none may be lost.
TEST(Oracle, LargeOffsetScenes) {
    for (double offset : {1e7, 1e8}) {
        const Outcome outcome = check_scene(offset_scene(3000, offset, 60.0, 3.0, 14));
        EXPECT_GT(outcome.oracle_pairs, 500u) << offset;
        EXPECT_GT(outcome.extra_pairs, 0u) << "offset " << offset << " should widen some boxes";
    }
}

TEST(Oracle, TouchingGridIsFoundExactly) {
    const std::size_t k = 12;
    const std::vector<Box> boxes = touching_grid(k);
    EXPECT_EQ(touching_grid_pairs(k), cgal_pairs(boxes).size());
    const Outcome outcome = check_scene(boxes, 5);
    EXPECT_EQ(touching_grid_pairs(k), outcome.oracle_pairs);
    EXPECT_EQ(0u, outcome.extra_pairs);
}

TEST(Oracle, DegenerateScene) {
    const std::vector<Box> boxes = degenerate_scene(15);
    const std::size_t s = kDegenerateFiller;  // the special boxes follow the filler, in this order:
    ASSERT_EQ(s + 63, boxes.size());
    const Outcome outcome = check_scene(boxes);
    const PairList oracle = cgal_pairs(boxes);
    auto in = [](const PairList& pairs, std::size_t i, std::size_t j) {
        return std::binary_search(pairs.begin(), pairs.end(),
                                  IndexPair{static_cast<uint32_t>(i), static_cast<uint32_t>(j)});
    };
    EXPECT_TRUE(in(oracle, s + 0, s + 1)) << "identical points";
    EXPECT_TRUE(in(oracle, s + 1, s + 2)) << "a point on a flat plate";
    std::size_t identical = 0;  // 40 identical boxes at s + 4 ..: all 780 pairs among them
    for (const IndexPair& p : oracle) identical += p.first >= s + 4 && p.second < s + 44;
    EXPECT_EQ(780u, identical);
    EXPECT_TRUE(in(oracle, s + 44, s + 45)) << "-0 touches +0";
    EXPECT_TRUE(in(oracle, s + 46, s + 47)) << "touching at a float denormal";
    EXPECT_FALSE(in(oracle, s + 48, s + 49)) << "one double denormal apart";
    EXPECT_FALSE(in(oracle, s + 50, s + 51)) << "2^-52 apart";
    EXPECT_TRUE(in(oracle, s + 54, s + 56)) << "the +inf point lies in the half-space";
    for (const IndexPair& p : oracle) EXPECT_TRUE(p.first != s + 55 && p.second != s + 55) << "the -inf point";
    EXPECT_FALSE(in(oracle, s + 58, s + 59)) << "apart near 1e300";
    EXPECT_TRUE(in(oracle, s + 61, s + 62)) << "the largest doubles touch";
    // Conversion bridges exactly these gaps: a double denormal (min rounds to
    // 0), 2^-52 at 1 (min rounds to 1), and beyond float range ([FLT_MAX, inf]).
    for (std::size_t i : {s + 48, s + 50, s + 58}) {
        EXPECT_TRUE(in(outcome.board, i, i + 1)) << "board misses the widened pair at " << i;
    }
    EXPECT_GE(outcome.extra_pairs, 3u);
}

// The oracle's doubles are what a trace of these scenes gives the CLI: a
// scene written as a trace reads back bit for bit (-0, denormals, DBL_MAX,
// infinities included).
TEST(Oracle, ScenesRoundTripThroughTheTraceFormat) {
    for (const std::vector<Box>& boxes : {degenerate_scene(15), offset_scene(500, 1e8, 60.0, 3.0, 14),
                                          clustered_scene(500, 4, 3.0, 2.0, 13)}) {
        Frame frame;
        frame.number = 3;
        frame.boxes = boxes;
        for (std::size_t k = 0; k < boxes.size(); ++k) frame.ids.push_back(k);
        std::stringstream text;
        write_trace_csv(text, {frame});
        const std::vector<Frame> read = parse_trace_csv(text, "scene.csv");
        ASSERT_EQ(1u, read.size());
        ASSERT_EQ(boxes.size(), read[0].boxes.size());
        EXPECT_EQ(0, std::memcmp(boxes.data(), read[0].boxes.data(), boxes.size() * sizeof(Box)));
    }
}

}  // namespace
}  // namespace cdvp::oracle
