// PairFinder's answers kept across runs in one process: a sweep of analytic
// points asks for the same scene's pairs again at every m, clock and bus
// (none of which changes them). Keyed by the number format and the six
// coordinate memories' words themselves (a hash finds the entry, the words
// are compared whole), so a hit is exact by construction; bounded in bytes,
// the least recently used entries going first. An entry also keeps its pairs
// in the orders callers asked for (a tiled board's block order), so that a
// hit costs a copy, not a sort.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "models/fast_engine/pair_finder.h"

namespace cdvp {

class PairMemo {
public:
    static constexpr std::size_t kDefaultBytes = std::size_t{256} << 20;
    explicit PairMemo(std::size_t max_bytes = kDefaultBytes) : max_bytes_(max_bytes) {}

    // A reordering of the finder's answer that depends on nothing but the
    // pairs and `key` (key 0 is the finder's own order, never a reordering).
    struct Order {
        uint64_t key = 0;
        std::function<void(PairList&)> apply;
    };

    // finder.find(objects, words, out), from the memo when it holds the same
    // words in the same format; a search that passes the finder's budget
    // throws as finder.find does and is not kept. With an order, `out` is
    // the answer reordered by it (kept too, under its key).
    void find(PairFinder& finder, uint32_t objects, const CoordinateWords& words, PairList& out,
              const Order* order = nullptr);

    std::size_t hits() const { return hits_; }
    std::size_t misses() const { return misses_; }
    std::size_t bytes() const { return bytes_; }

private:
    struct Entry {
        uint64_t key = 0;  // hash() of the rest
        std::string format;
        uint32_t objects = 0;
        std::vector<uint32_t> words;  // the six columns one after another
        PairList pairs;
        std::vector<std::pair<uint64_t, PairList>> orders;  // by Order::key
        std::size_t bytes() const {
            return words.size() * sizeof(uint32_t) + (1 + orders.size()) * (pairs.size() * sizeof(IndexPair) + 64) + 64;
        }
    };
    using Entries = std::list<Entry>;  // most recently used first
    static uint64_t hash(const std::string& format, uint32_t objects, const CoordinateWords& words);
    static bool same(const Entry& entry, const std::string& format, uint32_t objects, const CoordinateWords& words);
    // Drops least recently used entries until bytes() <= bytes; `keep` is never dropped.
    void evict_to(std::size_t bytes, const Entry* keep = nullptr);
    // A finder of `like`'s format and budget kept for the misses: its
    // buffers, sized by the searches before, are not allocated (and their
    // pages not touched for the first time) again for every search.
    PairFinder& searcher(const PairFinder& like);
    // `entry`'s pairs in `order`, reordered and kept the first time.
    const PairList& ordered(Entry& entry, const Order* order);

    std::size_t max_bytes_;
    std::size_t bytes_ = 0, hits_ = 0, misses_ = 0;
    Entries entries_;
    std::unordered_multimap<uint64_t, Entries::iterator> by_hash_;
    std::optional<PairFinder> searcher_;  // the last one used
};

// finder.find(objects, words, out), through `memo` when there is one.
// With an order, `out` is reordered by it.
inline void find_pairs(PairMemo* memo, PairFinder& finder, uint32_t objects, const CoordinateWords& words,
                       PairList& out, const PairMemo::Order* order = nullptr) {
    if (memo != nullptr) {
        memo->find(finder, objects, words, out, order);
    } else {
        finder.find(objects, words, out);
        if (order != nullptr && order->key != 0) order->apply(out);
    }
}

}  // namespace cdvp
