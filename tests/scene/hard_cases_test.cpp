// Checks the checked-in traces against their hand-derived expected pairs,
// using a naive all-pairs closed-interval test on the converted float boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <map>

#include "sw/scene/conversion.h"
#include "sw/scene/pairs_csv.h"
#include "sw/scene/trace_csv.h"

namespace cdvp {
namespace {

const std::string kTraces = std::string(CDVP_SOURCE_DIR) + "/traces/";

template <typename B>
bool overlap(const B& a, const B& b) {
    for (int axis = 0; axis < 3; ++axis) {
        if (!(a.min[axis] <= b.max[axis] && b.min[axis] <= a.max[axis])) return false;
    }
    return true;
}

template <typename B>
std::vector<IdPair> naive_pairs(const Frame& frame, const std::vector<B>& boxes) {
    PairList pairs;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        for (uint32_t j = i + 1; j < boxes.size(); ++j) {
            if (overlap(boxes[i], boxes[j])) pairs.push_back({i, j});
        }
    }
    return to_id_pairs(frame, pairs);
}

// Expected pairs grouped by frame number.
std::map<uint64_t, std::vector<IdPair>> read_expected(const std::string& path) {
    std::map<uint64_t, std::vector<IdPair>> by_frame;
    for (const auto& [frame, pair] : read_pairs_csv(path)) by_frame[frame].push_back(pair);
    return by_frame;
}

void check_trace(const std::string& stem) {
    std::vector<Frame> frames = read_trace_csv(kTraces + stem + ".csv");
    auto expected = read_expected(kTraces + stem + ".expected.csv");
    ASSERT_FALSE(frames.empty());
    for (const Frame& frame : frames) {
        EXPECT_EQ(expected[frame.number], naive_pairs(frame, to_float_boxes(frame.boxes)))
            << stem << " frame " << frame.number;
    }
    for (const auto& entry : expected) {
        EXPECT_TRUE(std::any_of(frames.begin(), frames.end(),
                                [&](const Frame& f) { return f.number == entry.first; }))
            << "expected pairs for missing frame " << entry.first;
    }
}

TEST(CheckedInTraces, HardCasesMatchExpected) {
    check_trace("hard_cases");
}

TEST(CheckedInTraces, SmallMatchesExpected) {
    check_trace("small");
}

TEST(CheckedInTraces, SpellingsMatchExpected) {
    check_trace("spellings");
}

// The pairs of a one-frame trace found in float but not in double; checks
// that every pair overlapping in double is found in float.
std::vector<IdPair> float_only_pairs(const std::string& stem) {
    std::vector<Frame> frames = read_trace_csv(kTraces + stem + ".csv");
    EXPECT_EQ(1u, frames.size());
    if (frames.size() != 1) return {};
    std::vector<IdPair> in_double = naive_pairs(frames[0], frames[0].boxes);
    std::vector<IdPair> in_float = naive_pairs(frames[0], to_float_boxes(frames[0].boxes));
    EXPECT_TRUE(std::includes(in_float.begin(), in_float.end(), in_double.begin(), in_double.end())) << stem;
    std::vector<IdPair> extra;
    std::set_difference(in_float.begin(), in_float.end(), in_double.begin(), in_double.end(),
                        std::back_inserter(extra));
    return extra;
}

// Conversion is conservative: the only extra pairs are the documented ones.
TEST(CheckedInTraces, FloatOnlyPairsAreTheDocumentedOnes) {
    EXPECT_EQ((std::vector<IdPair>{{45, 46}, {1100, 1101}}), float_only_pairs("hard_cases"));
    EXPECT_EQ((std::vector<IdPair>{{7, 8}}), float_only_pairs("spellings"));
}

}  // namespace
}  // namespace cdvp
