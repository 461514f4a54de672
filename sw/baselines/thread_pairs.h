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
        for (Own& own : lists_) own.pairs.clear(), own.reported = 0;
        counted_.store(0, std::memory_order_relaxed);
    }
    PairList& list(unsigned thread) { return lists_[thread].pairs; }

    // A thread's report after a piece of work: false once the frame's pairs
    // have passed the budget (stop looking).
    bool report(unsigned thread, const PairBudget& budget) {
        Own& own = lists_[thread];
        const uint64_t found = own.pairs.size() - own.reported;
        own.reported = own.pairs.size();
        const uint64_t total = counted_.fetch_add(found, std::memory_order_relaxed) + found;
        return total <= budget.max_pairs();
    }

    // Every thread's pairs in `out` (cleared first); PairBudgetExceeded past
    // the budget. One thread's list is handed over, not copied.
    void join(PairList& out, const PairBudget& budget) {
        std::size_t total = 0;
        for (const Own& own : lists_) total += own.pairs.size();
        budget.check(total);
        if (lists_.size() == 1) return out.swap(lists_[0].pairs);
        out.clear();
        out.reserve(total);
        for (const Own& own : lists_) out.insert(out.end(), own.pairs.begin(), own.pairs.end());
    }

private:
    // A thread's pairs and how many it has reported, on cache lines of their
    // own: a push_back writes the vector's end, and threads writing ends that
    // share a line would take it from each other at every pair.
    struct alignas(64) Own {
        PairList pairs;
        std::size_t reported = 0;
    };
    std::vector<Own> lists_;
    std::atomic<uint64_t> counted_{0};
};

}  // namespace cdvp
