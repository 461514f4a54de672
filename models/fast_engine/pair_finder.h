// Every pair the board's comparison unit accepts, found without the board's all-pairs sweep.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "models/common/aabb.h"
#include "models/common/pair_budget.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/fast_engine/box_block.h"

namespace cdvp {

// The six coordinate memories' contents: words[c][i] is the stored word of
// bound c (Coordinate order) of box i (float32 bits, or a fixed-point code).
using CoordinateWords = std::array<const uint32_t*, kCoordinates>;

// The words a float32 board stores for `boxes` (each bound's float bits),
// kept in `words`; the view reads them.
CoordinateWords float32_words(const std::vector<FloatBox>& boxes, std::vector<uint32_t> (&words)[kCoordinates]);

// Finds exactly the pairs (i, j), i < j < objects, for which the comparison
// unit's lane test in the given number format holds, in BoardCore's order (i
// ascending, then j ascending). Every bound becomes the format's ordered key
// (NumberFormat::key), so all comparisons are integer ones. Small scenes: all
// pairs over structure-of-arrays, four boxes a test. Larger ones: a sort on
// min x, boxes binned into a grid of y-z cells (in value space, from the
// format's monotone approximate value) and a sweep along x inside each cell
// (box pruning); a pair meeting in several cells is reported by the first one
// only. Any bound may be any word: a box with a word the format excludes
// (float32 NaN) meets nothing and is left out first; inverted boxes (min >
// max) are tested as the comparators would. Scratch memory is kept between
// calls; O(N + pairs).
//
// A search that finds more pairs than its budget throws PairBudgetExceeded
// as soon as it knows: the list of blocks with hits is checked when it
// grows (and only once it could hold more pairs than the budget), the pairs
// once they are counted. No list outgrows the budget by more than its first
// size (a block a box) or one doubling, and the per-block work is unchanged.
class PairFinder {
public:
    explicit PairFinder(NumberFormat format = NumberFormat::float32(), PairBudget budget = {})
        : format_(format), budget_(budget) {}
    NumberFormat format() const { return format_; }
    const PairBudget& budget() const { return budget_; }

    // At most this many boxes: all pairs (no sort pays off below it).
    static constexpr uint32_t kBruteForceLimit = 256;

    void find(uint32_t objects, const CoordinateWords& words, PairList& out);
    // The two algorithms, for tests and benchmarks: the same pairs in the same order.
    void all_pairs(uint32_t objects, const CoordinateWords& words, PairList& out);
    void sweep(uint32_t objects, const CoordinateWords& words, PairList& out);

    // Above this many boxes the sweep first groups them by cell, so that
    // filling the cells reads memory in order (below, they fit in the cache).
    static constexpr uint32_t kClusterAbove = 32768;
    // For tests: group by cell above `boxes` instead.
    void set_cluster_above(uint32_t boxes) { cluster_above_ = boxes; }

    // Grid cells of the last sweep (1 when it swept along x alone).
    uint32_t last_cells() const { return cells_y_ * cells_z_; }

    // A grid whose cell entries exceed this many per box (huge or infinite
    // boxes spanning many cells) is dropped for the plain sweep along x.
    static constexpr uint64_t kMaxEntriesPerBox = 4;
    // The most scratch a search keeps a box searched and a pair found, for
    // the memory estimate before a run (sw/run/run_footprint.h).
    static constexpr uint64_t scratch_bytes_per_box();
    static constexpr uint64_t scratch_bytes_per_pair();

private:
    struct Grid;
    // One box in 32 bytes: bounds, index, and its first y and z cells ((y << 16) | z).
    struct PackedBox {
        int32_t bound[kCoordinates];  // signed keys
        uint32_t index;
        uint32_t first_cell;
    };
    struct CellSpan {
        uint16_t y0, y1, z0, z1;
    };
    // A box in the min-x sort: its ordered key, its position in valid_ and its cells.
    struct SortItem {
        uint32_t key;
        uint32_t position;
        CellSpan span;
    };

    void load_valid(uint32_t objects, const CoordinateWords& words);
    // kFixed: the keys are fixed-point codes (else float32 keys).
    template <bool kFixed>
    Grid choose_grid() const;
    template <bool kFixed>
    void find_spans(const Grid& grid);
    void cluster_by_first_cell();
    void sort_by_min_x();
    // The cells a box touches when it touches at most two per axis: corner k
    // is (y0 + (k >> 1), z0 + (k & 1)), clamped to the span.
    struct CellCorners {
        uint32_t cell[4];
        uint32_t second_y, second_z;  // 1 when the span has a second cell on that axis
        bool wide;                    // more than two cells on some axis
    };
    CellCorners corners_of(const CellSpan& span) const;
    template <typename Visit>
    void for_each_cell(const CellSpan& span, Visit&& visit) const;
    void bin();
    void sweep_cells();
    // Doubles the list of hit blocks once the first `recorded` are filled,
    // after checking the pairs they hold against the budget.
    void grow_hit_blocks(std::size_t recorded);
    // Writes the pairs of the recorded hit blocks into unordered_: how many.
    std::size_t emit_pairs();
    // Sorts the first `found` pairs of unordered_ into out, BoardCore's order.
    void order(uint32_t objects, std::size_t found, PairList& out);
    template <typename Key>
    void counting_sort(uint32_t objects, const IndexPair* from, std::size_t count, IndexPair* to, Key key);

    NumberFormat format_;
    PairBudget budget_;
    CoordinateWords words_{};  // the current sweep's
    // The words' keys by coordinate, and whether a box has an excluded word.
    std::vector<int32_t> key_columns_[kCoordinates];
    std::vector<uint32_t> excluded_;
    // Boxes without an excluded bound, in index order or grouped by first cell.
    std::vector<PackedBox> valid_, clustered_;
    uint32_t cluster_above_ = kClusterAbove;
    std::vector<SortItem> items_, spare_items_;
    // The grid's cells in order, each holding its boxes in min-x order:
    // entry e is box valid_[entry_box_[e]], with its bounds, its index and
    // whether its cell is the box's first on y (bit 0) and on z (bit 1).
    uint32_t cells_y_ = 1, cells_z_ = 1;
    uint64_t entry_count_ = 0;
    std::vector<uint32_t> cell_begin_, cell_next_;
    std::vector<uint32_t> entry_box_;
    BoxColumns entries_;
    std::vector<uint32_t> entry_index_, entry_first_;  // kBlock words of padding each
    // A block of kBlock boxes from entry q0 with hits against entry p.
    struct HitBlock {
        uint32_t p, q0, hits;
    };
    // The hits of a block that the block's cell is the first cell to report:
    // the pairs it adds (emit_pairs).
    uint32_t first_cell_hits(const HitBlock& block) const;
    std::vector<HitBlock> hit_blocks_;  // the first hit_block_count_ are this sweep's
    std::size_t hit_block_count_ = 0;
    PairList unordered_;  // keeps its largest size: only a prefix is used
    std::vector<uint64_t> row_next_;
    BoxColumns all_;
};

// Keys and exclusion flags; boxes packed, and grouped by cell; sort items and
// their spare; up to kMaxEntriesPerBox cell entries (box, bounds, index,
// flags) and a block of hits each (the first list of hit blocks); row offsets.
constexpr uint64_t PairFinder::scratch_bytes_per_box() {
    const uint64_t entry = sizeof(uint32_t) + kCoordinates * sizeof(int32_t) + 2 * sizeof(uint32_t) + sizeof(HitBlock);
    return kCoordinates * sizeof(int32_t) + sizeof(uint32_t) + 2 * sizeof(PackedBox) + 2 * sizeof(SortItem) +
           kMaxEntriesPerBox * entry + sizeof(uint64_t);
}
// A block with hits holds at least one pair: its record (the list doubles as
// it grows), its kBlock unordered pairs; then the pair sorted (counted
// twice, as an earlier order step kept a second copy: an upper bound).
constexpr uint64_t PairFinder::scratch_bytes_per_pair() {
    return 2 * sizeof(HitBlock) + BoxColumns::kBlock * sizeof(IndexPair) + 2 * sizeof(IndexPair);
}

}  // namespace cdvp
