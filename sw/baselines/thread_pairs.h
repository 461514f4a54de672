// The pairs a multi-threaded baseline finds, one list a thread, held to the
// pair budget together: a thread adds what it found since its last report to
// a shared count, and once the count passes the budget every thread stops
// looking (the frame will be refused), so the lists stay near the budget.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "models/common/aabb.h"
#include "models/common/pair_budget.h"

namespace cdvp {

class ThreadPairs {
public:
    explicit ThreadPairs(unsigned threads) : lists_(threads) {}

    // Before a frame: empty lists, nothing counted.
    void clear() {
        for (PairList& list : lists_) list.clear();
        reported_.assign(lists_.size(), 0);
        counted_.store(0, std::memory_order_relaxed);
    }
    PairList& list(unsigned thread) { return lists_[thread]; }

    // A thread's report after a piece of work: false once the frame's pairs
    // have passed the budget (stop looking).
    bool report(unsigned thread, const PairBudget& budget) {
        const uint64_t found = lists_[thread].size() - reported_[thread];
        reported_[thread] = lists_[thread].size();
        const uint64_t total = counted_.fetch_add(found, std::memory_order_relaxed) + found;
        return total <= budget.max_pairs();
    }
    bool over(const PairBudget& budget) const { return counted_.load(std::memory_order_relaxed) > budget.max_pairs(); }

    // Every thread's pairs in `out` (cleared first); PairBudgetExceeded past
    // the budget. One thread's list is handed over, not copied.
    void join(PairList& out, const PairBudget& budget) {
        std::size_t total = 0;
        for (const PairList& list : lists_) total += list.size();
        budget.check(total);
        if (lists_.size() == 1) return out.swap(lists_[0]);
        out.clear();
        out.reserve(total);
        for (const PairList& list : lists_) out.insert(out.end(), list.begin(), list.end());
    }

private:
    std::vector<PairList> lists_;
    std::vector<std::size_t> reported_;
    std::atomic<uint64_t> counted_{0};
};

}  // namespace cdvp
