#include "models/grid_fast_engine/grid_search.h"

#include <algorithm>

#include "models/comparison_unit/comparison_unit.h"
#include "models/grid_fast_engine/cell_hits.h"

namespace cdvp {

GridSearch::GridSearch(const BoardConfig& config, PairBudget budget)
    : config_((config.validate(), config)), slots_(config.grid_slots()), budget_(budget), finder_(config.format, budget) {
    for (uint32_t k = 0; k < lane_slot_.size(); ++k) lane_slot_[k] = k / slots_.lanes;
}

uint64_t GridSearch::run(uint32_t objects, const CoordinateWords& words, PairList& pairs,
                         std::vector<uint64_t>& slots) {
    pairs.clear();
    slots.clear();
    stats_ = GridSweepStats{};
    large_.clear();
    if (objects < 2) return 0;  // no sweep, as on the seed's board
    const uint64_t placed = bin(objects, words);
    const uint64_t cells_end = sweep_cells(placed, pairs, slots);
    stats_.slots = sweep_large(cells_end, objects, words, pairs, slots);
    return stats_.slots;
}

uint64_t GridSearch::bin(uint32_t objects, const CoordinateWords& words) {
    const NumberFormat format = config_.format;
    const GridConfig& grid = config_.grid;
    // Pass 1: the bounds.
    GridBounds bounds(format);
    for (uint32_t begin = 0; begin < objects; begin += BoundRun::kBoxes) {
        bounds.add_run(words.data(), begin, std::min(BoundRun::kBoxes, objects - begin));
    }
    grid_ = bounds.geometry(grid, grid.dims_for(objects));
    stats_.dims = grid_.dims();
    // Pass 2's verdicts that need no count (excluded, inverted, spanning),
    // and each cell's boxes and first boxes were every candidate binned.
    const uint64_t cells = grid_.cells();
    boxes_.resize(objects);
    binned_.resize(objects);
    cell_words_.assign(cells, CellWords{});
    uint64_t count_slots = 0, entries = 0;
    uint32_t candidates = 0;
    // A run of boxes at a time: the keys and cells of each bound over the
    // run first (vectorized), then each box's verdict and counts.
    for (uint32_t begin = 0; begin < objects; begin += BoundRun::kBoxes) {
        const uint32_t n = std::min(BoundRun::kBoxes, objects - begin);
        grid_.fill_run(words.data(), begin, n, run_);
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t i = begin + k;
            Box& box = boxes_[i];
            Binned& b = binned_[i];
            for (uint32_t c = 0; c < kCoordinates; ++c) box.key[c] = run_.key[c][k];
            b.kind = run_.excluded[k] != 0 ? Kind::kExcluded : Kind::kBinned;
            uint64_t covered = 0;
            if (b.kind == Kind::kExcluded) {
                ++stats_.excluded_boxes;
            } else if (grid_.classify_run(run_, k, grid.max_span, b.range) == BoxClass::kCandidate) {
                covered = b.range.cells();
                ++candidates;
                entries += covered;
                ++cell_words_[grid_.linear(b.range.lo[0], b.range.lo[1], b.range.lo[2])].first;
                CellTable::for_each_cell(b.range, grid_, [&](uint64_t c) { ++cell_words_[c].boxes; });
            } else {
                b.kind = Kind::kLarge;
                large_.push_back(i);
            }
            box.index = i;
            box.first = b.range.lo;
            box.kind = b.kind;
            count_slots += slots_.box(covered);  // a candidate's counts are read whether it fits or not
        }
    }
    // No cell fills and the entries fit: every candidate binned, whatever
    // the order (pass 3 touches the cells pass 2 read); else box by box.
    uint32_t fullest = 0;  // the fullest cell's boxes
    for (const CellWords& w : cell_words_) fullest = std::max(fullest, w.boxes);
    const bool in_any_order = fullest <= grid.cell_capacity && entries <= grid.entry_capacity;
    if (in_any_order) bin_sorted(candidates, entries);
    const uint64_t place_slots = in_any_order ? count_slots : bin_in_order(objects);
    stats_.large_boxes = static_cast<uint32_t>(large_.size());
    return slots_.bounds(objects) + GridSlots::setup() + slots_.pass(count_slots) + grid_.cells() +
           slots_.pass(place_slots);
}

void GridSearch::bin_sorted(uint32_t candidates, uint64_t entries) {
    // The scan, and where each cell's first boxes go in placed_: a stable
    // counting sort of the candidates by first cell.
    busy_.clear();
    uint32_t next_box = 0, next_entry = 0;
    for (uint64_t c = 0; c < cell_words_.size(); ++c) {
        CellWords& w = cell_words_[c];
        const uint32_t firsts = w.first, n = w.boxes;
        w.first = next_box;
        w.boxes = next_entry;
        if (n >= 2) busy_.push_back({static_cast<uint32_t>(c), next_entry, n});
        next_box += firsts;
        next_entry += n;
    }
    // The candidates copied in first-cell order.
    placed_.resize(candidates);
    place_of_.resize(boxes_.size());
    for (const Box& b : boxes_) {
        if (b.kind != Kind::kBinned) continue;
        const uint32_t at = cell_words_[grid_.linear(b.first[0], b.first[1], b.first[2])].first++;
        placed_[at] = b;
        place_of_[b.index] = at;
    }
    // The place pass: each candidate's place entered in each of its cells,
    // in index order, as the board places them, so each list is in index order.
    lists_.resize(entries);
    for (uint32_t i = 0; i < binned_.size(); ++i) {
        const Binned& b = binned_[i];
        if (b.kind != Kind::kBinned) continue;
        const uint32_t at = place_of_[i];
        CellTable::for_each_cell(b.range, grid_, [&](uint64_t c) { lists_[cell_words_[c].boxes++] = at; });
    }
    sorted_lists_ = true;
    stats_.cell_entries = entries;
    stats_.busy_cells = static_cast<uint32_t>(busy_.size());
}

uint64_t GridSearch::bin_in_order(uint32_t objects) {
    const GridConfig& grid = config_.grid;
    table_.reset(grid_.cells(), grid.cell_capacity, grid.entry_capacity);
    large_.clear();
    for (uint32_t i = 0; i < objects; ++i) {
        Binned& b = binned_[i];
        if (b.kind == Kind::kBinned && !table_.count(b.range, grid_)) {
            b.kind = Kind::kLarge;
            boxes_[i].kind = Kind::kLarge;
            ++stats_.overflow_boxes;
        }
        if (b.kind == Kind::kLarge) large_.push_back(i);
    }
    stats_.cell_entries = table_.entries();
    table_.scan();
    uint64_t place_slots = 0;
    for (uint32_t i = 0; i < objects; ++i) {
        const Binned& b = binned_[i];
        const bool binned = b.kind == Kind::kBinned;
        if (binned) table_.place(i, b.range, grid_);
        place_slots += slots_.box(binned ? b.range.cells() : 0);
    }
    sorted_lists_ = false;
    stats_.busy_cells = static_cast<uint32_t>(table_.busy_cells().size());
    return place_slots;
}

void GridSearch::sweep_cell(const BusyCell& cell, uint64_t row_start, PairList& pairs, std::vector<uint64_t>& slots) {
    const uint32_t n = cell.count, dims = grid_.dims(), lanes = slots_.lanes;
    const uint32_t here[3] = {cell.cell % dims, cell.cell / dims % dims, cell.cell / dims / dims};
    // The keys as the lanes compare them; and, up to 64 boxes, which start
    // here on each axis: the one-cell rule keeps a pair only if, on every
    // axis, one of its two boxes starts here, so only such partners are tested.
    const bool masked = n <= 64;
    uint64_t starts[3] = {};
    for (uint32_t k = 0; k < n; ++k) {
        const Box& b = *cell_boxes_[k];
        for (uint32_t c = 0; c < kCoordinates; ++c) cell_columns_.bound[c][k] = static_cast<int32_t>(b.key[c] ^ 0x8000'0000u);
        if (masked) {
            small_.index[k] = b.index;
            for (uint32_t a = 0; a < 3; ++a) starts[a] |= uint64_t{b.first[a] == here[a]} << k;
        }
    }
    if (masked) {
        // Every row tested first (masked_cell_hits), then its hits turned into pairs.
        masked_cell_hits(cell_columns_, n, starts, small_.row_hits.data());
        add_small_cell(n, row_start, pairs, slots);
        return;
    }
    // Above 64 boxes: each row tested first, its hits gathered as bits, in
    // groups of four columns aligned to four, so none straddles a word.
    row_hits_.resize((n + 63) / 64);
    uint64_t* hit_words = row_hits_.data();
    for (uint32_t r = 0; r + 1 < n; ++r) {
        int32_t row[kCoordinates];
        cell_columns_.get(r, row);
        const BlockTest test(cell_columns_, row);
        const uint32_t first_word = (r + 1) / 64, end_word = (n + 63) / 64;
        for (uint32_t w = first_word; w < end_word; ++w) hit_words[w] = 0;
        const uint32_t aligned = (r + 1) & ~3u;
        for (uint32_t q0 = aligned; q0 < n; q0 += 4) {
            hit_words[q0 / 64] |= uint64_t{test.hits(q0) & block_mask_before(q0, n)} << (q0 % 64);
        }
        hit_words[first_word] &= ~uint64_t{0} << ((r + 1) % 64);
        const Box& a = *cell_boxes_[r];
        for (uint32_t w = first_word; w < end_word; ++w) {
            for (uint64_t hits = hit_words[w]; hits != 0; hits &= hits - 1) {
                const uint32_t c = w * 64 + static_cast<uint32_t>(__builtin_ctzll(hits));
                const Box& b = *cell_boxes_[c];
                // The one-cell rule.
                bool keep = true;
                for (uint32_t x = 0; x < 3; ++x) keep &= a.first[x] == here[x] || b.first[x] == here[x];
                if (keep) add(pairs, slots, {a.index, b.index}, row_start + (c - r - 1) / lanes);
            }
        }
        row_start += (n - 1 - r + lanes - 1) / lanes;  // ceil((n-1-r) / w)
    }
}

void GridSearch::add_small_cell(uint32_t n, uint64_t row_start, PairList& pairs, std::vector<uint64_t>& slots) {
    // The rows with hits and each row's first slot.
    uint64_t rows = 0;
    for (uint32_t r = 0; r + 1 < n; ++r) {
        rows |= uint64_t{small_.row_hits[r] != 0} << r;
        small_.row_slot[r] = row_start;
        row_start += lane_slot_[n - 2 - r] + 1;  // ceil((n-1-r) / w)
    }
    if (rows == 0) return;
    // One pair an iteration, rows and columns ascending, with no branch on
    // a row's hits: a row's last hit moves to the next row with hits (after
    // the last, to word 63, never a row of a cell, read but not used).
    uint64_t hits = small_.row_hits[__builtin_ctzll(rows)], found = 0;
    for (; rows != 0; ++found) {
        const auto r = static_cast<uint32_t>(__builtin_ctzll(rows));
        const auto c = static_cast<uint32_t>(__builtin_ctzll(hits));
        small_.pairs[found] = {small_.index[r], small_.index[c]};
        small_.slots[found] = small_.row_slot[r] + lane_slot_[c - r - 1];
        hits &= hits - 1;
        const bool row_done = hits == 0;
        rows = row_done ? rows & (rows - 1) : rows;
        hits = row_done ? small_.row_hits[__builtin_ctzll(rows | uint64_t{1} << 63)] : hits;
    }
    budget_.check_room(pairs.size(), found);
    pairs.insert(pairs.end(), small_.pairs.begin(), small_.pairs.begin() + static_cast<std::ptrdiff_t>(found));
    slots.insert(slots.end(), small_.slots.begin(), small_.slots.begin() + static_cast<std::ptrdiff_t>(found));
}

uint64_t GridSearch::sweep_cells(uint64_t begin, PairList& pairs, std::vector<uint64_t>& slots) {
    CellBlocks blocks(slots_, begin);
    const uint32_t capacity = config_.grid.cell_capacity;
    cell_columns_.resize(capacity + kCellHitsPadding);
    cell_boxes_.resize(capacity);
    if (!sorted_lists_) {
        // Lists of box indices in index order, as the board's.
        for (const BusyCell& cell : table_.busy_cells()) {
            const uint32_t* list = table_.list(cell);
            for (uint32_t k = 0; k < cell.count; ++k) cell_boxes_[k] = &boxes_[list[k]];
            sweep_cell(cell, blocks.add(cell.count), pairs, slots);
        }
        return blocks.end();
    }
    for (std::size_t b = 0; b < busy_.size(); ++b) {
        const BusyCell& cell = busy_[b];
        const uint32_t* list = lists_.data() + cell.first;
        for (uint32_t k = 0; k < cell.count; ++k) cell_boxes_[k] = &placed_[list[k]];
        // The next cell's boxes on their way into the cache while this one is swept.
        if (b + 1 < busy_.size()) {
            const BusyCell& next = busy_[b + 1];
            for (uint32_t k = 0; k < next.count; ++k) __builtin_prefetch(&placed_[lists_[next.first + k]]);
        }
        sweep_cell(cell, blocks.add(cell.count), pairs, slots);
    }
    return blocks.end();
}

}  // namespace cdvp
