// The grid board's last stage (docs/grid_board.md, "Large boxes"): the large
// boxes in tiles of cell_capacity, every box streamed past each tile. A
// binned box meets every box of the tile; a large one only the tile's boxes
// after it (each pair of large boxes once); an excluded one none.
#include <algorithm>

#include "models/grid_fast_engine/grid_search.h"

namespace cdvp {

void GridSearch::Tile::resize(uint32_t n) {
    if (index.size() >= n) return;
    for (auto& column : key) column.resize(n);
    index.resize(n);
}

void GridSearch::Tile::take(uint32_t at, const Box& b) {
    for (uint32_t c = 0; c < kCoordinates; ++c) key[c][at] = b.key[c];
    index[at] = b.index;
}

bool GridSearch::Tile::hit(const Box& row, uint32_t b) const {
    const uint32_t* r = row.key;
    return (r[kMinX] <= key[kMaxX][b]) & (key[kMinX][b] <= r[kMaxX]) & (r[kMinY] <= key[kMaxY][b]) &
           (key[kMinY][b] <= r[kMaxY]) & (r[kMinZ] <= key[kMaxZ][b]) & (key[kMinZ][b] <= r[kMaxZ]);
}

uint64_t GridSearch::sweep_large(uint64_t begin, uint32_t objects, const CoordinateWords& words, PairList& pairs,
                                 std::vector<uint64_t>& slots) {
    return large_.size() <= streamed_large_boxes_ ? stream_large(begin, objects, pairs, slots)
                                                  : search_large(begin, objects, words, pairs, slots);
}

// As the board runs it: N x L lane tests.
uint64_t GridSearch::stream_large(uint64_t begin, uint32_t objects, PairList& pairs, std::vector<uint64_t>& slots) {
    const auto large = static_cast<uint32_t>(large_.size());
    const uint32_t capacity = config_.grid.cell_capacity;
    const uint32_t lanes = slots_.lanes;
    uint64_t at = begin;
    for (uint32_t tile_begin = 0; tile_begin < large; tile_begin += capacity) {
        const uint32_t n = std::min(large - tile_begin, capacity);
        tile_.resize(n);
        for (uint32_t p = 0; p < n; ++p) tile_.take(p, boxes_[large_[tile_begin + p]]);
        at += slots_.tile_lead(n);
        uint32_t rank = 0;  // large boxes before j
        for (uint32_t j = 0; j < objects; ++j) {
            const Box& row = boxes_[j];
            uint32_t first = n;  // no columns
            if (row.kind == Kind::kBinned) {
                first = 0;
            } else if (row.kind == Kind::kLarge) {
                const uint32_t after = ++rank;
                first = after <= tile_begin ? 0 : std::min(after - tile_begin, n);
            }
            for (uint32_t p = first; p < n; ++p) {
                if (!tile_.hit(row, p)) continue;
                const uint32_t l = tile_.index[p];
                add(pairs, slots, {std::min(j, l), std::max(j, l)}, at + (p - first) / lanes);
            }
            at += slots_.stream_box(n - first);
        }
    }
    return at;
}

// One tile's stream in closed form. A row streamed past n columns from its
// column `first` costs stream_box(n - first) slots: a binned row all n, an
// excluded one none, and the large box of rank k (0-based) the columns after
// it, that is all n for k < tile_begin, n - 1 - (k - tile_begin) inside the
// tile, none after it.
struct GridSearch::TileStream {
    const GridSlots& slots;
    uint32_t tile_begin, n;
    std::vector<uint64_t> inside;  // inside[u]: the first u large rows inside the tile

    TileStream(const GridSlots& s, uint32_t begin, uint32_t boxes) : slots(s), tile_begin(begin), n(boxes), inside(n + 1) {
        for (uint32_t u = 0; u < n; ++u) inside[u + 1] = inside[u] + slots.stream_box(n - 1 - u);
    }
    // The first column a row of that kind and large rank compares.
    uint32_t first(Kind kind, uint32_t rank) const {
        if (kind == Kind::kBinned) return 0;
        if (kind == Kind::kExcluded) return n;
        const uint32_t after = rank + 1;
        return after <= tile_begin ? 0 : std::min(after - tile_begin, n);
    }
    // The slots of rows made of `binned`, `excluded` and `large` rows (the
    // large ones the first of the sweep's large boxes).
    uint64_t rows(uint64_t binned, uint64_t excluded, uint32_t large) const {
        const uint32_t before = std::min(large, tile_begin);
        const uint32_t within = std::min(large - before, n);
        return (binned + before) * slots.stream_box(n) + inside[within] +
               (excluded + (large - before - within)) * slots.stream_box(0);
    }
};

// The same pairs, order and slots from the all-pairs search: the pairs with
// a large box, each given its tile, row and column, sorted into the board's
// order, and each row's place in its tile's stream from the counts of the
// kinds before it.
uint64_t GridSearch::search_large(uint64_t begin, uint32_t objects, const CoordinateWords& words, PairList& pairs,
                                  std::vector<uint64_t>& slots) {
    const auto large = static_cast<uint32_t>(large_.size());
    const uint32_t capacity = config_.grid.cell_capacity;
    const auto rank_of = [&](uint32_t box) {
        return static_cast<uint32_t>(std::lower_bound(large_.begin(), large_.end(), box) - large_.begin());
    };
    try {
        finder_.find(objects, words, found_);
    } catch (const PairBudgetExceeded& e) {
        // Every pair is the grid's too: the board's list would pass the
        // budget, and stop at its first pair past it.
        throw PairBudgetExceeded(e.budget() + 1, e.budget());
    }
    large_hits_.clear();
    for (const IndexPair& p : found_) {
        const Kind a = boxes_[p.first].kind, b = boxes_[p.second].kind;
        if (a == Kind::kExcluded || b == Kind::kExcluded || (a == Kind::kBinned && b == Kind::kBinned)) continue;
        // Two large boxes meet in the later one's tile, on the earlier one's row.
        const bool second_large = b == Kind::kLarge;
        const uint32_t row = second_large ? p.first : p.second;
        const uint32_t column = rank_of(second_large ? p.second : p.first);
        large_hits_.push_back({column / capacity, row, column % capacity});
    }
    std::sort(large_hits_.begin(), large_hits_.end());
    binned_before_.assign(objects + 1, 0);
    excluded_before_.assign(objects + 1, 0);
    for (uint32_t j = 0; j < objects; ++j) {
        binned_before_[j + 1] = binned_before_[j] + (boxes_[j].kind == Kind::kBinned);
        excluded_before_[j + 1] = excluded_before_[j] + (boxes_[j].kind == Kind::kExcluded);
    }
    const auto large_before = [&](uint32_t j) { return j - binned_before_[j] - excluded_before_[j]; };
    uint64_t at = begin;
    auto hit = large_hits_.begin();
    for (uint32_t tile = 0, tile_begin = 0; tile_begin < large; ++tile, tile_begin += capacity) {
        const TileStream stream(slots_, tile_begin, std::min(large - tile_begin, capacity));
        at += slots_.tile_lead(stream.n);
        for (; hit != large_hits_.end() && hit->tile == tile; ++hit) {
            const uint32_t j = hit->row, rank = large_before(j);
            const uint64_t row_start = at + stream.rows(binned_before_[j], excluded_before_[j], rank);
            const uint32_t l = large_[tile_begin + hit->column];
            add(pairs, slots, {std::min(j, l), std::max(j, l)},
                row_start + (hit->column - stream.first(boxes_[j].kind, rank)) / slots_.lanes);
        }
        at += stream.rows(binned_before_[objects], excluded_before_[objects], large);
    }
    return at;
}

}  // namespace cdvp
