#include "models/pair_collector/pair_format.h"

#include <algorithm>

namespace cdvp {

namespace {
uint64_t row_words(uint32_t objects) { return (uint64_t{objects} + 31) / 32; }

uint64_t runs(const IndexPair* pairs, uint64_t count) {
    uint64_t runs = 0;
    for (uint64_t k = 0; k < count; ++k) runs += k == 0 || pairs[k].first != pairs[k - 1].first;
    return runs;
}

struct RowSpan {
    uint32_t first = 0, rows = 0;
};

RowSpan row_span(const IndexPair* pairs, uint64_t count) {
    if (count == 0) return {};
    uint32_t lo = pairs[0].first, hi = lo;
    for (uint64_t k = 1; k < count; ++k) {
        lo = std::min(lo, pairs[k].first);
        hi = std::max(hi, pairs[k].first);
    }
    return {lo, hi - lo + 1};
}
}  // namespace

uint64_t encoded_words(PairFormat format, const IndexPair* pairs, uint64_t count, uint32_t objects) {
    if (count == 0) return 0;
    switch (format) {
        case PairFormat::kList: return 2 * count;
        case PairFormat::kCounted: return 2 * runs(pairs, count) + count;
        case PairFormat::kBitmap: return 2 + row_span(pairs, count).rows * row_words(objects);
    }
    return 0;
}

uint64_t worst_encoded_words(PairFormat format, uint64_t pairs, uint32_t objects, uint64_t row_pieces) {
    if (pairs == 0) return 0;
    switch (format) {
        case PairFormat::kList: return 2 * pairs;
        case PairFormat::kCounted: {
            const uint64_t runs = row_pieces == 0 ? pairs : std::min(pairs, uint64_t{objects} * row_pieces);
            return 2 * runs + pairs;
        }
        case PairFormat::kBitmap: return 2 + uint64_t{objects} * row_words(objects);
    }
    return 0;
}

void encode_pairs(PairFormat format, const IndexPair* pairs, uint64_t count, uint32_t objects,
                  std::vector<uint32_t>& out) {
    if (count == 0) return;
    switch (format) {
        case PairFormat::kList:
            for (uint64_t k = 0; k < count; ++k) out.insert(out.end(), {pairs[k].first, pairs[k].second});
            return;
        case PairFormat::kCounted:
            for (uint64_t k = 0; k < count;) {
                uint64_t end = k + 1;
                while (end < count && pairs[end].first == pairs[k].first) ++end;
                out.insert(out.end(), {pairs[k].first, static_cast<uint32_t>(end - k)});
                for (; k < end; ++k) out.push_back(pairs[k].second);
            }
            return;
        case PairFormat::kBitmap: {
            const RowSpan span = row_span(pairs, count);
            const uint64_t width = row_words(objects), base = out.size() + 2;
            out.insert(out.end(), {span.first, span.rows});
            out.resize(base + span.rows * width, 0);
            for (uint64_t k = 0; k < count; ++k) {
                const uint64_t row = pairs[k].first - span.first;
                out[base + row * width + pairs[k].second / 32] |= 1u << (pairs[k].second % 32);
            }
            return;
        }
    }
}

namespace {
std::string check_pair(uint32_t first, uint32_t second, uint32_t objects) {
    if (first < second && second < objects) return {};
    return "pair (" + std::to_string(first) + ", " + std::to_string(second) + ") out of a sweep of " +
           std::to_string(objects) + " boxes";
}
}  // namespace

std::string decode_pairs(PairFormat format, const uint32_t* words, uint64_t count, uint32_t objects,
                         PairList& out) {
    switch (format) {
        case PairFormat::kList:
            if (count % 2 != 0) return "a pair list of an odd number of words";
            for (uint64_t k = 0; k < count; k += 2) {
                if (std::string e = check_pair(words[k], words[k + 1], objects); !e.empty()) return e;
                out.push_back({words[k], words[k + 1]});
            }
            return {};
        case PairFormat::kCounted:
            for (uint64_t k = 0; k < count;) {
                if (count - k < 2) return "a run header cut off at word " + std::to_string(k);
                const uint32_t first = words[k];
                const uint64_t length = words[k + 1];
                if (length == 0 || length > count - k - 2) {
                    return "a run of " + std::to_string(length) + " pairs at word " + std::to_string(k) +
                           " with " + std::to_string(count - k - 2) + " words left";
                }
                for (uint64_t w = k + 2; w < k + 2 + length; ++w) {
                    if (std::string e = check_pair(first, words[w], objects); !e.empty()) return e;
                    out.push_back({first, words[w]});
                }
                k += 2 + length;
            }
            return {};
        case PairFormat::kBitmap: {
            if (count == 0) return {};
            const uint64_t width = row_words(objects);
            if (count < 2 || count != 2 + uint64_t{words[1]} * width) {
                return "a bitmap of " + std::to_string(count) + " words that is not 2 + rows x " +
                       std::to_string(width);
            }
            for (uint64_t row = 0; row < words[1]; ++row) {
                const uint32_t first = words[0] + static_cast<uint32_t>(row);
                const uint32_t* bits = words + 2 + row * width;
                for (uint64_t w = 0; w < width; ++w) {
                    for (uint32_t v = bits[w]; v != 0; v &= v - 1) {
                        const auto second = static_cast<uint32_t>(w * 32 + __builtin_ctz(v));
                        if (std::string e = check_pair(first, second, objects); !e.empty()) return e;
                        out.push_back({first, second});
                    }
                }
            }
            return {};
        }
    }
    return "unknown pair format";
}

}  // namespace cdvp
