#include "models/fast_engine/pair_memo.h"

#include <cstring>

namespace cdvp {

uint64_t PairMemo::hash(const std::string& format, uint32_t objects, const CoordinateWords& words) {
    // FNV-1a over the format's name, then a multiply-mix a word (the splitmix64 finaliser).
    uint64_t h = 1469598103934665603ull;
    for (char c : format) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    h ^= objects;
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        for (uint32_t i = 0; i < objects; ++i) {
            h = (h ^ words[c][i]) * 0x9E3779B97F4A7C15ull;
            h ^= h >> 29;
        }
    }
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

void PairMemo::find(PairFinder& finder, uint32_t objects, const CoordinateWords& words, PairList& out) {
    const std::string format = finder.format().name();
    const uint64_t key = hash(format, objects, words);
    const auto [first, last] = by_hash_.equal_range(key);
    for (auto at = first; at != last; ++at) {
        const Entry& entry = *at->second;
        // A list past this finder's budget is found again, so that it throws as the finder does.
        if (!same(entry, format, objects, words) || entry.pairs.size() > finder.budget().max_pairs()) continue;
        out = entry.pairs;
        entries_.splice(entries_.begin(), entries_, at->second);
        ++hits_;
        return;
    }
    ++misses_;
    finder.find(objects, words, out);
    Entry entry{key, format, objects, {}, out};
    entry.words.resize(std::size_t{kCoordinates} * objects);
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        if (objects > 0) std::memcpy(&entry.words[std::size_t{c} * objects], words[c], objects * sizeof(uint32_t));
    }
    const std::size_t size = entry.bytes();
    if (size > max_bytes_) return;  // larger than the whole memo: not kept
    evict_to(max_bytes_ - size);
    entries_.push_front(std::move(entry));
    by_hash_.emplace(key, entries_.begin());
    bytes_ += size;
}

void PairMemo::evict_to(std::size_t bytes) {
    while (bytes_ > bytes && !entries_.empty()) {
        const auto last = std::prev(entries_.end());
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
