// All pairs over structure-of-arrays bounds, written for the auto-vectorizer:
// the host-side speed limit of the board's own algorithm (no pruning at all).
#pragma once

#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"

namespace cdvp {

class SoaBroadPhase : public BroadPhase {
public:
    std::string name() const override { return "soa"; }
    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) override;

    // Boxes j are tested in blocks of this many; the arrays are padded to whole blocks.
    static constexpr std::size_t kBlock = 64;

private:
    void load(const std::vector<FloatBox>& boxes);

    // lo_[axis][j] = boxes[j].min[axis], hi_[axis][j] = boxes[j].max[axis].
    std::vector<float> lo_[3];
    std::vector<float> hi_[3];
};

}  // namespace cdvp
