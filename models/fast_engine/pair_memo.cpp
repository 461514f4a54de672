#include "models/fast_engine/pair_memo.h"

#include <cstring>

namespace cdvp {

uint64_t PairMemo::hash(const std::string& format, uint32_t objects, const CoordinateWords& words) {
    // FNV-1a over the format's name; then each column, two words at a time,
    // into four lanes that do not wait for each other (a word's multiply-mix,
    // the splitmix64 finaliser's, is the chain's latency), merged at the end.
    // Equal keys are compared in full, so the hash need only spread.
    constexpr uint64_t kMix = 0x9E3779B97F4A7C15ull;
    uint64_t h = 1469598103934665603ull;
    for (char c : format) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    h ^= objects;
    uint64_t lane[4] = {h, h ^ 1, h ^ 2, h ^ 3};
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        const uint32_t* column = words[c];
        uint32_t i = 0;
        for (; i + 8 <= objects; i += 8) {
            for (int k = 0; k < 4; ++k) {
                uint64_t two;
                std::memcpy(&two, column + i + 2 * k, sizeof two);
                lane[k] = (lane[k] ^ two) * kMix;
                lane[k] ^= lane[k] >> 29;
            }
        }
        for (; i < objects; ++i) {
            lane[0] = (lane[0] ^ column[i]) * kMix;
            lane[0] ^= lane[0] >> 29;
        }
    }
    for (int k = 0; k < 4; ++k) h = ((h ^ lane[k]) * kMix) ^ (h >> 31);
    return h;
}

bool PairMemo::same(const Entry& entry, const std::string& format, uint32_t objects, const CoordinateWords& words) {
    if (entry.objects != objects || entry.format != format) return false;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        if (objects > 0 && std::memcmp(&entry.words[std::size_t{c} * objects], words[c], objects * sizeof(uint32_t)) != 0) {
            return false;
        }
    }
    return true;
}

const PairList& PairMemo::ordered(Entry& entry, const Order* order) {
    if (order == nullptr || order->key == 0) return entry.pairs;
    for (const auto& [key, pairs] : entry.orders) {
        if (key == order->key) return pairs;
    }
    PairList pairs = entry.pairs;
    order->apply(pairs);
    const std::size_t before = entry.bytes();
    entry.orders.emplace_back(order->key, std::move(pairs));
    bytes_ += entry.bytes() - before;
    return entry.orders.back().second;
}

void PairMemo::find(PairFinder& finder, uint32_t objects, const CoordinateWords& words, PairList& out,
                    const Order* order) {
    const std::string& format = finder.format().name();
    const uint64_t key = hash(format, objects, words);
    const auto [first, last] = by_hash_.equal_range(key);
    for (auto at = first; at != last; ++at) {
        Entry& entry = *at->second;
        // A list past this finder's budget is found again, so that it throws as the finder does.
        if (!same(entry, format, objects, words) || entry.pairs.size() > finder.budget().max_pairs()) continue;
        entries_.splice(entries_.begin(), entries_, at->second);
        out = ordered(entry, order);
        ++hits_;
        evict_to(max_bytes_, &entry);
        return;
    }
    ++misses_;
    searcher(finder).find(objects, words, out);
    Entry entry{key, format, objects, {}, out, {}};
    entry.words.resize(std::size_t{kCoordinates} * objects);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        if (objects > 0) std::memcpy(&entry.words[std::size_t{c} * objects], words[c], objects * sizeof(uint32_t));
    }
    const std::size_t size = entry.bytes();
    if (size > max_bytes_) {  // larger than the whole memo: not kept
        if (order != nullptr && order->key != 0) order->apply(out);
        return;
    }
    evict_to(max_bytes_ - size);
    entries_.push_front(std::move(entry));
    by_hash_.emplace(key, entries_.begin());
    bytes_ += size;
    if (order != nullptr && order->key != 0) {  // else `out` is the finder's answer already
        out = ordered(entries_.front(), order);
        evict_to(max_bytes_, &entries_.front());
    }
}

PairFinder& PairMemo::searcher(const PairFinder& like) {
    // One kept: a finder's buffers grow with N, and a point holds one anyway.
    if (!searcher_ || searcher_->format().name() != like.format().name() ||
        searcher_->budget().max_pairs() != like.budget().max_pairs()) {
        searcher_.emplace(like.format(), like.budget());
    }
    return *searcher_;
}

void PairMemo::evict_to(std::size_t bytes, const Entry* keep) {
    while (bytes_ > bytes && !entries_.empty()) {
        const auto last = std::prev(entries_.end());
        if (&*last == keep) return;  // the entry in use stays, even over the bound
        for (auto [at, end] = by_hash_.equal_range(last->key); at != end; ++at) {
            if (at->second == last) {
                by_hash_.erase(at);
                break;
            }
        }
        bytes_ -= last->bytes();
        entries_.erase(last);
    }
}

}  // namespace cdvp
