// The exactness wrapper shared by the baselines that time another library's
// broad phase (FCL's managers, ODE's spaces): the library finds candidate
// pairs among the boxes it can hold; every candidate is kept only if it passes
// the exact float32 closed-interval test (boxes_overlap), first < second; the
// boxes the library cannot hold are tested against every box here, one by one.
#pragma once

#include <cstdint>
#include <vector>

#include "sw/baselines/broad_phase.h"

namespace cdvp {

// Where a library reports its candidates (from its own callback): the exact
// test, and the pair budget without throwing (an exception must not unwind
// through a C library's collide, which holds its space locked meanwhile).
class CandidateSink {
public:
    CandidateSink(const std::vector<FloatBox>& boxes, const std::vector<char>& held, const PairBudget& budget,
                  PairList& out)
        : boxes_(boxes), held_(held), budget_(budget), out_(out) {}
    // False once the budget is full: a library that can stop may stop.
    bool offer(uint32_t a, uint32_t b);
    // Throws PairBudgetExceeded as budget.push would have, if a pair did not fit.
    void finish() const;
    uint64_t offered() const { return offered_; }

private:
    const std::vector<FloatBox>& boxes_;
    const std::vector<char>& held_;
    const PairBudget& budget_;
    PairList& out_;
    bool full_ = false;
    IndexPair over_{};
    uint64_t offered_ = 0;
};

// What the library did, for tests and curious callers: that the pairs come
// from it, and whether a frame was an update or a build.
struct LibraryCounts {
    uint64_t builds = 0;      // structures built (a new box count, or a move the library cannot take)
    uint64_t updates = 0;     // frames handed to the library's update
    uint64_t candidates = 0;  // pairs the library reported in the last frame
    std::size_t held = 0;     // boxes in the library in the last frame
};

class LibraryBroadPhase : public BroadPhase {
public:
    void find_pairs(const std::vector<FloatBox>& boxes, PairList& out) final;
    const LibraryCounts& counts() const { return counts_; }

protected:
    // Whether the library may hold this box. Never NaN or inverted boxes (min >
    // max on an axis); a library adds what else it cannot represent.
    virtual bool holds(const FloatBox& box) const;
    // A new box count, before holds() is asked: settings taken from the boxes.
    virtual void configure(const std::vector<FloatBox>& /*boxes*/) {}
    // Then the library's structure with the boxes held registered.
    virtual void build(const std::vector<FloatBox>& boxes, const std::vector<char>& held) = 0;
    // The same boxes moved: `left` leave the library, `entered` join it (both
    // rare: a box turned hostile or back), every held box takes its new bounds.
    virtual void update(const std::vector<FloatBox>& boxes, const std::vector<char>& held,
                        const std::vector<uint32_t>& left, const std::vector<uint32_t>& entered) = 0;
    // The library's candidate pairs of the held boxes, each to sink.offer.
    virtual void collide(CandidateSink& sink) = 0;
    // Drops the library's structure (the next call builds it again).
    virtual void reset() = 0;
    // An update that built the structure again instead.
    void count_rebuild() {
        ++counts_.builds;
        --counts_.updates;
    }

private:
    void pairs_of_outsiders(const std::vector<FloatBox>& boxes, PairList& out) const;

    LibraryCounts counts_;
    bool built_ = false;
    std::vector<char> held_;  // per box: in the library (1) or tested here (0)
    std::vector<uint32_t> outsiders_, left_, entered_;
};

// A float bound as a double one ulp (of double) further out: the library's
// set then holds every touching pair even where it compares strictly or breaks
// ties between equal ends its own way, and the exact test drops the extras.
double widened_low(float v);
double widened_high(float v);

}  // namespace cdvp
