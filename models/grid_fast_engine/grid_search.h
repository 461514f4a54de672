// The grid board's sweep as results (docs/grid_board.md): the binning passes
// in bulk, then each busy cell's pairs and each large tile's, in the board's
// order, each with the slot in which the board compares it. The clocked
// engine finds the same by walking the passes slot by slot; here each pass
// is one loop and each slot a closed form (GridSlots).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "models/board_spec/board_config.h"
#include "models/cell_memory/cell_table.h"
#include "models/common/pair_budget.h"
#include "models/fast_engine/box_block.h"
#include "models/fast_engine/pair_finder.h"
#include "models/grid_binning/grid_geometry.h"
#include "models/grid_schedule/grid_slots.h"

namespace cdvp {

class GridSearch {
public:
    // A sweep whose pairs outgrow `budget` throws PairBudgetExceeded in run().
    explicit GridSearch(const BoardConfig& config, PairBudget budget = {});

    // A sweep of boxes 0..objects-1: its pairs in the board's order (first <
    // second), pair k compared in slot slots[k]; returns the end marker's
    // slot (every slot of the sweep; 0 below two boxes).
    uint64_t run(uint32_t objects, const CoordinateWords& words, PairList& pairs, std::vector<uint64_t>& slots);
    const GridSweepStats& stats() const { return stats_; }

    // Up to this many large boxes, each box is streamed past every large
    // tile as the board does (N x L lane tests); above, the pairs with a
    // large box are found by the all-pairs search (O(N + pairs), as the
    // all-pairs board's fast engine costs) and placed in closed form. The
    // same pairs, order and slots either way.
    static constexpr uint32_t kStreamedLargeBoxes = 64;
    // For tests: search above `large` large boxes instead.
    void set_searched_above(uint32_t large) { streamed_large_boxes_ = large; }
    // The most a sweep of `objects` boxes keeps, in either grid engine, for
    // the memory estimate before a run: the count words and busy-cell list
    // a cell; a box's cells and kind, its keys by index and its copy in
    // first-cell order, its entries (each a list word and a word of the cell
    // table's lists), its place in that order and in the large list.
    static uint64_t scratch_bytes(const GridConfig& grid, uint64_t objects) {
        if (objects < 2) return 0;
        return grid.cells_for(objects) * (sizeof(CellWords) + 2 * sizeof(BusyCell)) +
               objects * (sizeof(Binned) + 2 * sizeof(Box) + grid.max_span * 2 * sizeof(uint32_t) + 4 * sizeof(uint32_t));
    }
    // The large sweep's search, a pair found: the pair, and its place in the board's order.
    static constexpr uint64_t scratch_bytes_per_pair() { return sizeof(IndexPair) + sizeof(LargeHit); }

private:
    enum class Kind : uint8_t { kBinned, kLarge, kExcluded };
    // A box as the cell sweep and the large sweep see it: its keys
    // (Coordinate order), its index, its first cell and its kind; 32 bytes,
    // two to a cache line.
    struct alignas(32) Box {
        uint32_t key[kCoordinates];
        uint32_t index;
        std::array<uint8_t, 3> first;
        Kind kind;
    };
    static_assert(sizeof(Box) == 32, "a box is half a cache line");
    // A box as pass 2 leaves it: its cells and kind, a word.
    struct alignas(8) Binned {
        CellRange range;
        Kind kind;
    };
    // A cell's count words: its first boxes and its boxes, counted in pass
    // 2, then (the scan) where they go in placed_ and in lists_.
    struct CellWords {
        uint32_t first = 0;
        uint32_t boxes = 0;
    };
    // A pair of the large sweep, where the board compares it: the large tile,
    // the streamed box (the row) and its column in the tile.
    struct LargeHit {
        uint32_t tile, row, column;
        friend bool operator<(const LargeHit& a, const LargeHit& b) {
            return a.tile != b.tile ? a.tile < b.tile : a.row != b.row ? a.row < b.row : a.column < b.column;
        }
    };
    // A large tile, gathered: keys by coordinate and indices.
    struct Tile {
        std::vector<uint32_t> key[kCoordinates];
        std::vector<uint32_t> index;
        void resize(uint32_t n);
        void take(uint32_t at, const Box& b);
        bool hit(const Box& row, uint32_t b) const;
    };

    // Passes 1 to 3 and the scan; the slot after the place pass.
    uint64_t bin(uint32_t objects, const CoordinateWords& words);
    // The scan and pass 3 when no cell fills and the entries fit (then the
    // order of the boxes cannot matter): the candidates copied in first-cell
    // order into placed_ and their places entered in the lists.
    void bin_sorted(uint32_t candidates, uint64_t entries);
    // Passes 2 and 3 box by box in index order, as the board runs them:
    // boxes meeting a full cell or entry memory become large. The place
    // pass's box slots.
    uint64_t bin_in_order(uint32_t objects);
    // The triangle of a busy cell's boxes (cell_boxes_, in index order) from
    // slot `row_start` on: up to 64 boxes, only where the one-cell rule may
    // keep a pair, as wide as the CPU compares (masked_cell_hits); above,
    // four lane tests at a time.
    void sweep_cell(const BusyCell& cell, uint64_t row_start, PairList& pairs, std::vector<uint64_t>& slots);
    // The pairs of a cell of up to 64 boxes from its rows' hits (small_),
    // its first row compared from slot `row_start` on.
    void add_small_cell(uint32_t n, uint64_t row_start, PairList& pairs, std::vector<uint64_t>& slots);
    // The busy cells from slot `begin` on; the slot after the last one's last compare.
    uint64_t sweep_cells(uint64_t begin, PairList& pairs, std::vector<uint64_t>& slots);
    // The large tiles from slot `begin` on; the slot after the last stream
    // (grid_large_sweep.cpp): streamed, or searched.
    uint64_t sweep_large(uint64_t begin, uint32_t objects, const CoordinateWords& words, PairList& pairs,
                         std::vector<uint64_t>& slots);
    uint64_t stream_large(uint64_t begin, uint32_t objects, PairList& pairs, std::vector<uint64_t>& slots);
    uint64_t search_large(uint64_t begin, uint32_t objects, const CoordinateWords& words, PairList& pairs,
                          std::vector<uint64_t>& slots);
    // Where a row's first compare falls in a tile's stream: the slots of the
    // rows before it (TileStream, grid_large_sweep.cpp).
    struct TileStream;
    void add(PairList& pairs, std::vector<uint64_t>& slots, IndexPair pair, uint64_t slot) const {
        budget_.push(pairs, pair);
        slots.push_back(slot);
    }

    BoardConfig config_;
    GridSlots slots_;
    PairBudget budget_;
    GridGeometry grid_;
    std::vector<Box> boxes_;      // every box by index
    std::vector<Binned> binned_;  // every box's cells, by index
    BoundRun run_;                // pass 2's run of boxes
    std::vector<uint32_t> large_;  // ascending
    // The busy cells and their lists (in index order): positions in placed_,
    // the binned boxes copied in first-cell order so that a cell's boxes lie
    // near each other in memory (bin_sorted); or box indices in table_
    // (bin_in_order).
    bool sorted_lists_ = false;
    std::vector<Box> placed_;
    std::vector<uint32_t> place_of_;  // a binned box's position in placed_
    std::vector<CellWords> cell_words_;
    std::vector<uint32_t> lists_;
    std::vector<BusyCell> busy_;
    CellTable table_;
    // The busy cell being swept, in index order: its boxes, and for a large
    // cell their keys as BlockTest takes them.
    std::vector<const Box*> cell_boxes_;
    BoxColumns cell_columns_;
    std::vector<uint64_t> row_hits_;  // above 64 boxes: a row's hits, a bit a column
    // A cell of up to 64 boxes: its boxes' indices, each row's hits (a bit a
    // column) and first slot, and its pairs before they are appended.
    struct SmallCell {
        std::array<uint32_t, 64> index;
        std::array<uint64_t, 64> row_hits;
        std::array<uint64_t, 64> row_slot;
        std::array<IndexPair, 64 * 63 / 2> pairs;
        std::array<uint64_t, 64 * 63 / 2> slots;
    };
    SmallCell small_{};
    std::array<uint32_t, 64> lane_slot_{};  // k / lanes: the slot of a row's k-th next column
    Tile tile_;
    // The large sweep's search: every pair, those with a large box, and the
    // binned and excluded boxes before each index.
    PairFinder finder_;
    PairList found_;
    std::vector<LargeHit> large_hits_;
    std::vector<uint32_t> binned_before_, excluded_before_;
    uint32_t streamed_large_boxes_ = kStreamedLargeBoxes;
    GridSweepStats stats_;
};

}  // namespace cdvp
