// Types shared by the hardware models, the reference and the host software.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cdvp {

// An axis-aligned bounding box as the board stores it: six float32 bounds,
// closed intervals (touching boxes overlap). Axis 0..2 = x, y, z.
struct FloatBox {
    float min[3];
    float max[3];
};

// A pair of box indices (positions in the uploaded frame), first < second.
struct IndexPair {
    uint32_t first;
    uint32_t second;
    friend bool operator==(const IndexPair& a, const IndexPair& b) {
        return a.first == b.first && a.second == b.second;
    }
    friend bool operator<(const IndexPair& a, const IndexPair& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    }
};

using PairList = std::vector<IndexPair>;

// A pair list in (first, second) order, the order in which results are compared.
inline PairList sorted(PairList pairs) {
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

}  // namespace cdvp
