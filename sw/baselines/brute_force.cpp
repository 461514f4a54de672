#include "sw/baselines/brute_force.h"

#include <utility>

namespace cdvp {

size_t brute_force_pairs(const std::vector<FloatBox>& boxes, PairList& out, const PairBudget& budget) {
    out.clear();
    const auto n = static_cast<uint32_t>(boxes.size());
    for (uint32_t i = 0; i < n; ++i) {
        for (uint32_t j = i + 1; j < n; ++j) {
            if (boxes_overlap(boxes[i], boxes[j])) budget.push(out, {i, j});
        }
    }
    return out.size();
}

PairList reference_pairs(const std::vector<FloatBox>& boxes) {
    PairList pairs;
    brute_force_pairs(boxes, pairs);
    return sorted(std::move(pairs));  // already in order; sorting states the contract
}

}  // namespace cdvp
