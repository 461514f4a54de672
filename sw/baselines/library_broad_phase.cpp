#include "sw/baselines/library_broad_phase.h"

#include <cmath>
#include <utility>

#include "sw/baselines/brute_force.h"

namespace cdvp {

bool CandidateSink::offer(uint32_t a, uint32_t b) {
    if (full_) return false;
    ++offered_;
    if (a > b) std::swap(a, b);
    // A library never pairs a box with itself; the check costs nothing beside the test.
    if (a == b || !held_[a] || !held_[b] || !boxes_overlap(boxes_[a], boxes_[b])) return true;
    if (out_.size() >= budget_.max_pairs()) {
        full_ = true;
        over_ = {a, b};
        return false;
    }
    out_.push_back({a, b});
    return true;
}

void CandidateSink::finish() const {
    if (full_) budget_.push(out_, over_);  // throws: the list is at the budget
}

bool LibraryBroadPhase::holds(const FloatBox& box) const {
    for (int axis = 0; axis < 3; ++axis) {
        // Also false for a NaN bound: a NaN box overlaps nothing.
        if (!(box.min[axis] <= box.max[axis])) return false;
    }
    return true;
}

void LibraryBroadPhase::find_pairs(const std::vector<FloatBox>& boxes, PairList& out) {
    out.clear();
    outsiders_.clear();
    if (!built_ || boxes.size() != held_.size()) {
        reset();
        built_ = false;
        held_.assign(boxes.size(), 0);
        configure(boxes);
        for (std::size_t i = 0; i < boxes.size(); ++i) held_[i] = holds(boxes[i]) ? 1 : 0;
        build(boxes, held_);
        built_ = true;
        ++counts_.builds;
    } else {
        left_.clear();
        entered_.clear();
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const char now = holds(boxes[i]) ? 1 : 0;
            if (now == held_[i]) continue;
            (now ? entered_ : left_).push_back(static_cast<uint32_t>(i));
            held_[i] = now;
        }
        ++counts_.updates;
        update(boxes, held_, left_, entered_);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (!held_[i]) outsiders_.push_back(static_cast<uint32_t>(i));
    }
    CandidateSink sink(boxes, held_, budget_, out);
    collide(sink);
    counts_.candidates = sink.offered();
    counts_.held = boxes.size() - outsiders_.size();
    sink.finish();
    pairs_of_outsiders(boxes, out);
}

// Each box the library does not hold against every other box: a pair of two
// such boxes once, from the lower index.
void LibraryBroadPhase::pairs_of_outsiders(const std::vector<FloatBox>& boxes, PairList& out) const {
    for (const uint32_t o : outsiders_) {
        for (std::size_t j = 0; j < boxes.size(); ++j) {
            if (j == o || (!held_[j] && j < o)) continue;
            if (!boxes_overlap(boxes[o], boxes[j])) continue;
            const auto other = static_cast<uint32_t>(j);
            budget_.push(out, o < other ? IndexPair{o, other} : IndexPair{other, o});
        }
    }
}

double widened_low(float v) { return std::nextafter(static_cast<double>(v), -INFINITY); }
double widened_high(float v) { return std::nextafter(static_cast<double>(v), INFINITY); }

}  // namespace cdvp
