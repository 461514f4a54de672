// The most pairs one frame may hold anywhere in a run (the setting
// run.max_pairs). A frame whose pairs cannot fit is refused where its pairs
// are found, before the memory for them is spent, rather than growing until
// the allocator gives up.
//
// Every stage that collects a frame's pairs goes through one PairBudget: the
// fast engine's pair search (models/fast_engine/pair_finder.h, also behind the
// fixed-point reference), the driver's read-back of the board's pair buffer
// (every engine's pairs pass through it) and each software baseline. Later
// stages (the pairs kept, the pairs CSV, the application) hold at most the
// driver's pairs, so they are bounded by the same check. docs/numerics.md:
// "Budgets before work".
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "models/common/aabb.h"

namespace cdvp {

// A frame's pairs outgrew the budget: at least found() of them, against
// budget() (a search stops at its first check past the budget, so found() is
// where it stopped, not the frame's total).
class PairBudgetExceeded : public std::runtime_error {
public:
    PairBudgetExceeded(uint64_t found, uint64_t budget)
        : std::runtime_error(std::to_string(found) + " pairs found, more than the pair budget of " +
                             std::to_string(budget)),
          found_(found),
          budget_(budget) {}
    uint64_t found() const { return found_; }
    uint64_t budget() const { return budget_; }

private:
    uint64_t found_;
    uint64_t budget_;
};

class PairBudget {
public:
    static constexpr uint64_t kUnlimited = std::numeric_limits<uint64_t>::max();

    constexpr PairBudget() = default;
    explicit constexpr PairBudget(uint64_t max_pairs) : max_pairs_(max_pairs) {}

    uint64_t max_pairs() const { return max_pairs_; }
    bool unlimited() const { return max_pairs_ == kUnlimited; }

    // Before a list grows to `pairs`: throws PairBudgetExceeded past the budget.
    void check(uint64_t pairs) const {
        if (pairs > max_pairs_) throw PairBudgetExceeded(pairs, max_pairs_);
    }
    // Appends one pair, or throws PairBudgetExceeded when the list is full:
    // for loops that find a pair at a time (one compare beside the vector's own).
    void push(PairList& list, const IndexPair& pair) const {
        if (list.size() >= max_pairs_) throw PairBudgetExceeded(uint64_t{list.size()} + 1, max_pairs_);
        list.push_back(pair);
    }

    // Before `more` pairs are appended to a list of `size`: throws as push()
    // would at the first pair past the budget (for loops that count a
    // block's pairs before appending them).
    void check_room(uint64_t size, uint64_t more) const {
        if (more > max_pairs_ - std::min(size, max_pairs_)) throw PairBudgetExceeded(max_pairs_ + 1, max_pairs_);
    }

private:
    uint64_t max_pairs_ = kUnlimited;
};

}  // namespace cdvp
