#include "models/fast_engine/pair_finder.h"

#include <algorithm>
#include <cmath>

namespace cdvp {

namespace {

constexpr std::size_t kBlock = BoxColumns::kBlock;
// Cells per axis at most, and boxes per cell at least (on average): below
// that the binning costs more than the sweep it saves.
constexpr uint32_t kMaxCellsPerAxis = 1024;
constexpr uint32_t kMinBoxesPerCell = 16;
// Rows of at most this many pairs are ordered by insertion.
constexpr uint64_t kInsertionSortRow = 32;

// The unsigned key of a signed one: the order the radix sort sorts by.
uint32_t unsigned_key(int32_t key) { return static_cast<uint32_t>(key) ^ 0x8000'0000u; }

// Visits the set bits of a block's hit mask as box positions.
template <typename Visit>
void for_each_hit(uint32_t hits, std::size_t q0, Visit&& visit) {
    while (hits != 0) {
        visit(q0 + static_cast<std::size_t>(__builtin_ctz(hits)));
        hits &= hits - 1;
    }
}

}  // namespace

CoordinateWords float32_words(const std::vector<FloatBox>& boxes, std::vector<uint32_t> (&words)[kCoordinates]) {
    CoordinateWords view{};
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        words[c].resize(boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            words[c][i] = ComparisonUnit::as_bits(c < 3 ? boxes[i].min[c] : boxes[i].max[c - 3]);
        }
        view[c] = words[c].data();
    }
    return view;
}

// The y-z grid: cell of v on an axis = floor((v - origin) / size), clamped,
// v a stored word's value (the float for float32, the code for fixedK: the
// approximate value of its key, read from the word so no key is undone).
// Float arithmetic: each step is monotonic in the key, which is all the sweep
// needs (boxes whose hulls meet get spans that meet); -0 and +0, one key, give
// one cell.
struct PairFinder::Grid {
    uint32_t cells[2] = {1, 1};  // y, z
    float origin[2] = {0, 0};
    float inverse_size[2] = {0, 0};

    // kFixed: fixed-point codes (mask: the format's word mask); else float32.
    // A template parameter, so the per-box loops carry no test of the format.
    template <bool kFixed>
    static float value(uint32_t word, uint32_t mask) {
        return kFixed ? NumberFormat::fixed_value(word & mask) : ComparisonUnit::as_float(word);
    }
    uint16_t cell(int axis, float value) const {
        if (cells[axis] == 1) return 0;  // (and inverse_size 0 would turn infinities into NaN)
        const float at = (value - origin[axis]) * inverse_size[axis];
        // Clamped first, so truncation is floor and infinities land in the end cells; a NaN
        // (a box that meets nothing) lands in cell 0: max(0, NaN) is 0, where max(NaN, 0) is
        // NaN, which no integer holds.
        return static_cast<uint16_t>(std::min(std::max(0.0f, at), static_cast<float>(cells[axis] - 1)));
    }
};

void PairFinder::find(uint32_t objects, const CoordinateWords& words, PairList& out) {
    if (objects <= kBruteForceLimit) {
        all_pairs(objects, words, out);
    } else {
        sweep(objects, words, out);
    }
}

// Over the boxes the format does not exclude, in index order: pairs come out
// in BoardCore's order.
void PairFinder::all_pairs(uint32_t objects, const CoordinateWords& words, PairList& out) {
    out.clear();
    load_valid(objects, words);
    const std::size_t n = valid_.size();
    all_.resize(n);
    for (std::size_t k = 0; k < n; ++k) all_.set(k, valid_[k].bound);
    for (std::size_t p = 0; p < n; ++p) {
        int32_t a[kCoordinates];
        all_.get(p, a);
        const BlockTest test(all_, a);
        const uint32_t i = valid_[p].index;
        for (std::size_t q0 = p + 1; q0 < n; q0 += kBlock) {
            const uint32_t hits = test.hits(q0) & block_mask_before(q0, n);
            for_each_hit(hits, q0, [&](std::size_t q) { out.push_back({i, valid_[q].index}); });
        }
        budget_.check(out.size());  // a row adds fewer than n pairs
    }
}

void PairFinder::sweep(uint32_t objects, const CoordinateWords& words, PairList& out) {
    words_ = words;
    load_valid(objects, words);
    if (format_.is_float()) {
        find_spans<false>(choose_grid<false>());
    } else {
        find_spans<true>(choose_grid<true>());
    }
    cluster_by_first_cell();
    sort_by_min_x();
    bin();
    sweep_cells();
    order(objects, emit_pairs(), out);
}

// Keys a column at a time (a loop the compiler vectorises), then the boxes
// packed from them, those with an excluded word (float32 NaN) left out.
void PairFinder::load_valid(uint32_t objects, const CoordinateWords& words) {
    excluded_.assign(objects, 0);
    uint32_t* excluded = excluded_.data();
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        key_columns_[c].resize(objects);
        int32_t* keys = key_columns_[c].data();
        const uint32_t* column = words[c];
        if (format_.is_float()) {
            for (uint32_t i = 0; i < objects; ++i) {
                keys[i] = signed_key(NumberFormat::float32(), column[i]);
                excluded[i] |= NumberFormat::float32().excluded(column[i]) ? 1u : 0u;
            }
        } else {
            const NumberFormat format = format_;
            for (uint32_t i = 0; i < objects; ++i) keys[i] = signed_key(format, column[i]);
        }
    }
    valid_.resize(objects);
    std::size_t kept = 0;
    for (uint32_t i = 0; i < objects; ++i) {
        PackedBox& box = valid_[kept];
        for (uint32_t c = 0; c < kCoordinates; ++c) box.bound[c] = key_columns_[c][i];
        box.index = i;
        box.first_cell = 0;
        kept += excluded[i] == 0 ? 1 : 0;  // every comparison with a NaN is false: it meets nothing
    }
    valid_.resize(kept);
}

// Cells about twice the mean box extent, so that most boxes touch one or two
// cells per axis; none over kMaxCellsPerAxis a side or with fewer than
// kMinBoxesPerCell boxes on average.
template <bool kFixed>
PairFinder::Grid PairFinder::choose_grid() const {
    Grid grid;
    const std::size_t n = valid_.size();
    for (int axis = 0; axis < 2; ++axis) {
        double low = INFINITY, high = -INFINITY, extent = 0;
        std::size_t finite = 0;
        const uint32_t* lows = words_[kMinY + axis];
        const uint32_t* highs = words_[kMaxY + axis];
        const uint32_t mask = format_.word_mask();
        for (const PackedBox& box : valid_) {
            const float lo = Grid::value<kFixed>(lows[box.index], mask);
            const float hi = Grid::value<kFixed>(highs[box.index], mask);
            if (!std::isfinite(lo) || !std::isfinite(hi)) continue;
            low = std::min<double>(low, std::min(lo, hi));
            high = std::max<double>(high, std::max(lo, hi));
            extent += std::fabs(static_cast<double>(hi) - lo);
            ++finite;
        }
        if (finite == 0 || !(high > low)) continue;
        const double size = std::max(2.0 * extent / static_cast<double>(finite), (high - low) / kMaxCellsPerAxis);
        const double cells = std::floor((high - low) / size);
        grid.cells[axis] = static_cast<uint32_t>(std::clamp(cells, 1.0, static_cast<double>(kMaxCellsPerAxis)));
        grid.origin[axis] = static_cast<float>(low);
        grid.inverse_size[axis] = static_cast<float>(grid.cells[axis] / (high - low));
    }
    while (uint64_t{grid.cells[0]} * grid.cells[1] > std::max<uint64_t>(n / kMinBoxesPerCell, 1)) {
        // Coarsen the finer axis first.
        const int axis = grid.cells[0] >= grid.cells[1] ? 0 : 1;
        grid.inverse_size[axis] *= static_cast<float>(static_cast<double>((grid.cells[axis] + 1) / 2) / grid.cells[axis]);
        grid.cells[axis] = (grid.cells[axis] + 1) / 2;
    }
    return grid;
}

// The cells of each box's y and z hulls [min(lo, hi), max(lo, hi)]: two boxes
// that meet on an axis have intersecting hulls even when inverted. Each box
// becomes a sort item: its min-x key, its position in valid_ and its cells.
template <bool kFixed>
void PairFinder::find_spans(const Grid& chosen) {
    const std::size_t n = valid_.size();
    Grid grid = chosen;
    items_.resize(n);
    const uint32_t mask = format_.word_mask();
    const auto value = [&](uint32_t c, uint32_t i) { return Grid::value<kFixed>(words_[c][i], mask); };
    for (int attempt = 0; attempt < 2; ++attempt) {
        entry_count_ = 0;
        for (std::size_t k = 0; k < n; ++k) {
            PackedBox& box = valid_[k];
            const int32_t* b = box.bound;
            const float y0 = value(kMinY, box.index), y1 = value(kMaxY, box.index);
            const float z0 = value(kMinZ, box.index), z1 = value(kMaxZ, box.index);
            const CellSpan span = {grid.cell(0, std::min(y0, y1)), grid.cell(0, std::max(y0, y1)),
                                   grid.cell(1, std::min(z0, z1)), grid.cell(1, std::max(z0, z1))};
            entry_count_ += uint64_t{span.y1 - span.y0 + 1u} * (span.z1 - span.z0 + 1u);
            box.first_cell = (uint32_t{span.y0} << 16) | span.z0;
            items_[k] = {unsigned_key(b[kMinX]), static_cast<uint32_t>(k), span};
        }
        if (entry_count_ <= kMaxEntriesPerBox * n) break;
        grid = Grid{};  // huge boxes everywhere: one cell
    }
    cells_y_ = grid.cells[0];
    cells_z_ = grid.cells[1];
}

// Boxes grouped by their first cell (a counting sort), so that the boxes of
// one cell lie close together when the cells are filled: index order says
// nothing about where a box is. Pays off only once the boxes outgrow the
// cache.
void PairFinder::cluster_by_first_cell() {
    const std::size_t n = valid_.size();
    if (n <= cluster_above_) return;
    cell_begin_.assign(std::size_t{cells_y_} * cells_z_ + 1, 0);
    auto first_cell = [&](const SortItem& item) { return uint32_t{item.span.y0} * cells_z_ + item.span.z0; };
    for (const SortItem& item : items_) ++cell_begin_[first_cell(item) + 1];
    for (std::size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
    cell_next_.assign(cell_begin_.begin(), cell_begin_.end() - 1);
    clustered_.resize(n);
    spare_items_.resize(n);
    for (const SortItem& item : items_) {
        const uint32_t position = cell_next_[first_cell(item)]++;
        clustered_[position] = valid_[item.position];
        spare_items_[position] = {item.key, position, item.span};
    }
    valid_.swap(clustered_);
    items_.swap(spare_items_);
}

// LSD radix sort of the boxes' (min x key, position, cells), 11 bits a pass;
// a pass whose digit is the same for every box is skipped.
void PairFinder::sort_by_min_x() {
    const std::size_t n = items_.size();
    spare_items_.resize(n);
    for (uint32_t shift = 0; shift < 32; shift += 11) {
        std::size_t count[2048 + 1] = {};
        for (const SortItem& item : items_) ++count[((item.key >> shift) & 2047) + 1];
        if (n == 0 || count[((items_[0].key >> shift) & 2047) + 1] == n) continue;
        for (std::size_t d = 1; d <= 2048; ++d) count[d] += count[d - 1];
        for (const SortItem& item : items_) spare_items_[count[(item.key >> shift) & 2047]++] = item;
        items_.swap(spare_items_);
    }
}

// Lays the boxes out cell by cell, each cell in min-x order: a stable counting
// sort of the x-sorted boxes by cell, moving only positions (one write stream
// per cell), then one pass gathering the bounds. Most boxes touch one or two
// cells per axis: those are counted and placed without a branch on their span
// (an unpredictable branch per box costs more than the rest of the pass).
void PairFinder::bin() {
    const std::size_t cells = std::size_t{cells_y_} * cells_z_;
    cell_begin_.assign(cells + 1, 0);
    uint32_t* count = cell_begin_.data() + 1;
    for (const SortItem& item : items_) {
        const CellCorners corners = corners_of(item.span);
        if (corners.wide) {
            for_each_cell(item.span, [&](uint32_t cell) { ++count[cell]; });
            continue;
        }
        ++count[corners.cell[0]];
        count[corners.cell[1]] += corners.second_z;
        count[corners.cell[2]] += corners.second_y;
        count[corners.cell[3]] += corners.second_y & corners.second_z;
    }
    for (std::size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
    cell_next_.assign(cell_begin_.begin(), cell_begin_.end() - 1);
    // One spare slot at the end takes the writes of corners a box does not touch.
    entry_box_.resize(entry_count_ + 1);
    const std::size_t spare = entry_count_;
    uint32_t* next = cell_next_.data();
    for (const SortItem& item : items_) {
        const CellCorners corners = corners_of(item.span);
        if (corners.wide) {
            for_each_cell(item.span, [&](uint32_t cell) { entry_box_[next[cell]++] = item.position; });
            continue;
        }
        const uint32_t touched[4] = {1, corners.second_z, corners.second_y, corners.second_y & corners.second_z};
        for (int k = 0; k < 4; ++k) {
            uint32_t& slot = next[corners.cell[k]];
            entry_box_[touched[k] != 0 ? slot : spare] = item.position;
            slot += touched[k];
        }
    }
    entries_.resize(entry_count_);
    entry_index_.resize(entry_count_ + kBlock);
    entry_first_.resize(entry_count_ + kBlock);
    // The boxes a little ahead on their way into the cache: entries of one
    // cell come from boxes of several first cells, far apart.
    constexpr std::size_t kAhead = 16;
    for (uint32_t cell = 0; cell < cells; ++cell) {
        const uint32_t y = cell / cells_z_, z = cell % cells_z_;
        for (uint32_t e = cell_begin_[cell]; e < cell_begin_[cell + 1]; ++e) {
            if (e + kAhead < entry_count_) __builtin_prefetch(&valid_[entry_box_[e + kAhead]]);
            const PackedBox& box = valid_[entry_box_[e]];
            entries_.set(e, box.bound);
            entry_index_[e] = box.index;
            entry_first_[e] = ((box.first_cell >> 16) == y ? 1u : 0u) | ((box.first_cell & 0xFFFF) == z ? 2u : 0u);
        }
    }
}

PairFinder::CellCorners PairFinder::corners_of(const CellSpan& span) const {
    CellCorners corners;
    corners.wide = span.y1 - span.y0 > 1 || span.z1 - span.z0 > 1;
    corners.second_y = span.y1 != span.y0 ? 1u : 0u;
    corners.second_z = span.z1 != span.z0 ? 1u : 0u;
    const uint32_t first = uint32_t{span.y0} * cells_z_ + span.z0;
    corners.cell[0] = first;
    corners.cell[1] = first + corners.second_z;
    corners.cell[2] = first + corners.second_y * cells_z_;
    corners.cell[3] = corners.cell[2] + corners.second_z;
    return corners;
}

template <typename Visit>
void PairFinder::for_each_cell(const CellSpan& span, Visit&& visit) const {
    for (uint32_t y = span.y0; y <= span.y1; ++y) {
        for (uint32_t z = span.z0; z <= span.z1; ++z) visit(y * cells_z_ + z);
    }
}

// Box pruning in each cell: box p meets only boxes q after it (min x order)
// with min_x(q) <= max_x(p), a prefix of the cell's rest; the block test does
// the six comparisons, so blocks running past the prefix add nothing. About
// half the blocks tested hold a hit, too irregular for the branch predictor,
// so the sweep only records blocks with hits (without a branch) and
// emit_pairs() turns them into pairs afterwards.
void PairFinder::sweep_cells() {
    const int32_t* min_x = entries_.bound[kMinX].data();
    hit_blocks_.resize(std::max<std::size_t>(hit_blocks_.size(), entry_count_ + 1));
    std::size_t recorded = 0;
    for (uint32_t cell = 0; cell + 1 < cell_begin_.size(); ++cell) {
        const std::size_t end = cell_begin_[cell + 1];
        for (std::size_t p = cell_begin_[cell]; p < end; ++p) {
            int32_t a[kCoordinates];
            entries_.get(p, a);
            const BlockTest test(entries_, a);
            for (std::size_t q0 = p + 1; q0 < end; q0 += kBlock) {
                const uint32_t hits = test.hits(q0) & block_mask_before(q0, end);
                if (recorded + 1 == hit_blocks_.size()) grow_hit_blocks(recorded);
                hit_blocks_[recorded] = {static_cast<uint32_t>(p), static_cast<uint32_t>(q0), hits};
                recorded += hits != 0 ? 1 : 0;
                if (q0 + kBlock >= end || !(min_x[q0 + kBlock - 1] <= a[kMaxX])) break;
            }
        }
    }
    hit_block_count_ = recorded;
}

// Both boxes of a hit are in the block's cell, so it is the first cell they
// share exactly when it is the first on y of one of them and the first on z
// of one of them; the others are dropped. Every lane is written and the end
// moves on by the lane's hit bit: no branch per hit.
inline uint32_t PairFinder::first_cell_hits(const HitBlock& block) const {
    const uint32_t* first = entry_first_.data();
    const uint32_t own = first[block.p];
    const uint32_t any_y = (own & 1) != 0 ? ~0u : 0u, any_z = (own & 2) != 0 ? ~0u : 0u;
    return block.hits & (any_y | block_flag_bits<0>(first, block.q0)) & (any_z | block_flag_bits<1>(first, block.q0));
}

// Until the blocks could hold more pairs than the budget (kBlock a block at
// most) nothing is counted, so a search within its budget does no more work
// than before; past that, the pairs of the blocks so far are counted exactly
// (a pair met in several cells once), each time the list doubles.
void PairFinder::grow_hit_blocks(std::size_t recorded) {
    if (uint64_t{kBlock} * recorded > budget_.max_pairs()) {
        uint64_t pairs = 0;
        for (std::size_t r = 0; r < recorded; ++r) {
            pairs += static_cast<uint64_t>(__builtin_popcount(first_cell_hits(hit_blocks_[r])));
        }
        budget_.check(pairs);
    }
    hit_blocks_.resize(2 * hit_blocks_.size());
}

std::size_t PairFinder::emit_pairs() {
    const uint32_t* index = entry_index_.data();
    unordered_.resize(std::max<std::size_t>(unordered_.size(), kBlock * (hit_block_count_ + 1)));
    IndexPair* out = unordered_.data();
    std::size_t found = 0;
    for (std::size_t r = 0; r < hit_block_count_; ++r) {
        const HitBlock& block = hit_blocks_[r];
        const uint32_t hits = first_cell_hits(block);
        const uint32_t i = index[block.p];
        for (std::size_t k = 0; k < kBlock; ++k) {
            const uint32_t j = index[block.q0 + k];  // padding past the cell's end: never counted
            out[found].first = std::min(i, j);
            out[found].second = std::max(i, j);
            found += (hits >> k) & 1u;
        }
    }
    budget_.check(found);  // before the ordered lists are sized for them
    return found;
}

// BoardCore's order: a counting sort on the first index (no comparisons),
// then each row, a few pairs, put in order of the second by insertion.
void PairFinder::order(uint32_t objects, std::size_t found, PairList& out) {
    out.resize(found);
    counting_sort(objects, unordered_.data(), found, out.data(), [](const IndexPair& pair) { return pair.first; });
    // row_next_[r] is now the end of row r.
    IndexPair* pairs = out.data();
    uint64_t begin = 0;
    for (uint32_t r = 0; r < objects; ++r) {
        const uint64_t end = row_next_[r];
        if (end - begin > kInsertionSortRow) {  // a box meeting many: no quadratic insertion
            std::sort(pairs + begin, pairs + end, [](const IndexPair& a, const IndexPair& b) { return a.second < b.second; });
            begin = end;
            continue;
        }
        for (uint64_t k = begin + 1; k < end; ++k) {
            const IndexPair pair = pairs[k];
            uint64_t at = k;
            for (; at > begin && pairs[at - 1].second > pair.second; --at) pairs[at] = pairs[at - 1];
            pairs[at] = pair;
        }
        begin = end;
    }
}

template <typename Key>
void PairFinder::counting_sort(uint32_t objects, const IndexPair* from, std::size_t count, IndexPair* to, Key key) {
    row_next_.assign(std::size_t{objects} + 1, 0);
    uint64_t* next = row_next_.data();
    for (std::size_t k = 0; k < count; ++k) ++next[key(from[k]) + 1];
    for (std::size_t r = 1; r < row_next_.size(); ++r) next[r] += next[r - 1];
    for (std::size_t k = 0; k < count; ++k) to[next[key(from[k])]++] = from[k];
}

}  // namespace cdvp
