#include "sw/baselines/parallel_sap.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "sw/baselines/box_bounds.h"

namespace cdvp {

ParallelSapBroadPhase::ParallelSapBroadPhase(unsigned threads)
    : pool_(threads == 0 ? machine_threads() : threads), found_(pool_.size()) {}

// Frame coherence: the same boxes moved a little keep nearly the order they
// had, which an insertion sort puts right in about one pass; otherwise (a
// new count, a NaN, another axis) the boxes are sorted afresh.
void ParallelSapBroadPhase::sort_boxes(const std::vector<FloatBox>& boxes) {
    const std::size_t kept = index_.size();
    std::vector<uint32_t> whole;
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        if (!has_nan(boxes[i])) whole.push_back(i);
    }
    // lo_[0] and hi_[0] hold the swept axis, the other two the rest.
    const int swept = widest_axis(boxes, whole);
    const auto before = [&](uint32_t a, uint32_t b) {
        return boxes[a].min[swept] < boxes[b].min[swept] || (boxes[a].min[swept] == boxes[b].min[swept] && a < b);
    };
    bool sorted = false;
    if (whole.size() == boxes.size() && kept == boxes.size() && swept == swept_ && boxes.size() == frame_boxes_) {
        // Past a few moves a box, the boxes jumped: a fresh sort is quicker.
        std::size_t moves = 0;
        const std::size_t limit = 8 * index_.size();
        for (std::size_t k = 1; k < index_.size() && moves <= limit; ++k) {
            const uint32_t moving = index_[k];
            std::size_t j = k;
            for (; j > 0 && before(moving, index_[j - 1]); --j) index_[j] = index_[j - 1];
            index_[j] = moving;
            moves += k - j;
        }
        sorted = moves <= limit;
    }
    if (!sorted) {
        index_ = std::move(whole);
        std::sort(index_.begin(), index_.end(), before);
    }
    swept_ = swept;
    frame_boxes_ = boxes.size();
    for (int slot = 0; slot < 3; ++slot) {
        const int axis = (swept + slot) % 3;
        lo_[slot].resize(index_.size());
        hi_[slot].resize(index_.size());
        for (std::size_t k = 0; k < index_.size(); ++k) {
            lo_[slot][k] = boxes[index_[k]].min[axis];
            hi_[slot][k] = boxes[index_[k]].max[axis];
        }
    }
}

// Every box after k in the sorted list starts no earlier, so once one starts
// after k ends, none of the rest can overlap k. The whole test is made on
// each candidate (an inverted box, min above max, overlaps as the reference
// says it does).
void ParallelSapBroadPhase::sweep(unsigned thread) {
    PairList& mine = found_.list(thread);
    const std::size_t n = index_.size();
    const float* const lo[3] = {lo_[0].data(), lo_[1].data(), lo_[2].data()};
    const float* const hi[3] = {hi_[0].data(), hi_[1].data(), hi_[2].data()};
    while (true) {
        const std::size_t start = next_.fetch_add(kChunk, std::memory_order_relaxed);
        if (start >= n) return;
        for (std::size_t k = start; k < std::min(start + kChunk, n); ++k) {
            for (std::size_t j = k + 1; j < n && lo[0][j] <= hi[0][k]; ++j) {
                if (lo[0][k] <= hi[0][j] && lo[1][j] <= hi[1][k] && lo[1][k] <= hi[1][j] && lo[2][j] <= hi[2][k] &&
                    lo[2][k] <= hi[2][j]) {
                    mine.push_back({std::min(index_[k], index_[j]), std::max(index_[k], index_[j])});
                }
            }
        }
        // Past the budget the frame is refused: stop looking, so the pairs
        // held stay near the budget, not the frame's whole count.
        if (!found_.report(thread, budget_)) return;
    }
}

void ParallelSapBroadPhase::find_pairs(const std::vector<FloatBox>& boxes, PairList& out) {
    out.clear();
    sort_boxes(boxes);
    found_.clear();
    next_.store(0);
    pool_.run([this](unsigned thread) { sweep(thread); });
    found_.join(out, budget_);
}

}  // namespace cdvp
