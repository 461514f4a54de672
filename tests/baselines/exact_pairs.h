// The baselines' tests' one check: a baseline's pairs on a scene, sorted,
// equal reference_pairs' (each pair once, first < second); a failure lists
// the first pairs missing and the first extra (or duplicated) ones.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <sstream>
#include <string>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/brute_force.h"
#include "tests/baselines/scenes.h"

namespace cdvp::test {

inline std::string first_pairs(const PairList& pairs) {
    std::ostringstream text;
    for (std::size_t k = 0; k < pairs.size() && k < 8; ++k) {
        text << " (" << pairs[k].first << "," << pairs[k].second << ")";
    }
    if (pairs.size() > 8) text << " ...";
    return text.str();
}

// Returns the reference so callers can check the scene itself.
inline PairList expect_exact(BroadPhase& phase, const Boxes& boxes, const std::string& what) {
    PairList got;
    phase.find_pairs(boxes, got);
    std::sort(got.begin(), got.end());
    const PairList want = reference_pairs(boxes);
    PairList missing, extra;
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
    EXPECT_TRUE(missing.empty() && extra.empty() && got.size() == want.size())
        << phase.name() << " on " << what << " (" << boxes.size() << " boxes): " << want.size()
        << " pairs expected, " << got.size() << " found; missing" << first_pairs(missing) << "; extra (or duplicated)"
        << first_pairs(extra);
    return want;
}

}  // namespace cdvp::test
