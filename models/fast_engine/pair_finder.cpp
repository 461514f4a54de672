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
// A grid whose cell entries exceed this many per box (huge or infinite
// boxes spanning many cells) is dropped for the plain sweep along x.
constexpr uint64_t kMaxEntriesPerBox = 4;

void read_box(const CoordinateWords& words, uint32_t i, float (&bounds)[kCoordinates]) {
    for (uint32_t c = 0; c < kCoordinates; ++c) bounds[c] = ComparisonUnit::as_float(words[c][i]);
}

// Float bits mapped to unsigned integers in the floats' order (-0 just below
// +0, which compare equal: either order is fine for the sweep).
uint32_t ordered_key(float value) {
    const uint32_t bits = ComparisonUnit::as_bits(value);
    return (bits & 0x8000'0000u) != 0 ? ~bits : bits | 0x8000'0000u;
}

// Visits the set bits of a block's hit mask as box positions.
template <typename Visit>
void for_each_hit(uint32_t hits, std::size_t q0, Visit&& visit) {
    while (hits != 0) {
        visit(q0 + static_cast<std::size_t>(__builtin_ctz(hits)));
        hits &= hits - 1;
    }
}

}  // namespace

// The y-z grid: cell of v on an axis = floor((v - origin) / size), clamped.
struct PairFinder::Grid {
    uint32_t cells[2] = {1, 1};  // y, z
    double origin[2] = {0, 0};
    double inverse_size[2] = {0, 0};

    uint16_t cell(int axis, float value) const {
        if (cells[axis] == 1) return 0;
        const double at = (static_cast<double>(value) - origin[axis]) * inverse_size[axis];
        // Clamped first, so truncation is floor (and infinities land in the end cells).
        return static_cast<uint16_t>(std::min(std::max(at, 0.0), static_cast<double>(cells[axis] - 1)));
    }
};

void PairFinder::find(uint32_t objects, const CoordinateWords& words, PairList& out) {
    if (objects <= kBruteForceLimit) {
        all_pairs(objects, words, out);
    } else {
        sweep(objects, words, out);
    }
}

void PairFinder::all_pairs(uint32_t objects, const CoordinateWords& words, PairList& out) {
    out.clear();
    all_.resize(objects);
    for (uint32_t i = 0; i < objects; ++i) {
        float bounds[kCoordinates];
        read_box(words, i, bounds);
        all_.set(i, bounds);
    }
    for (uint32_t i = 0; i < objects; ++i) {
        float a[kCoordinates];
        all_.get(i, a);
        const BlockTest test(all_, a);
        for (std::size_t q0 = i + 1; q0 < objects; q0 += kBlock) {
            const uint32_t hits = test.hits(q0) & block_mask_before(q0, objects);
            for_each_hit(hits, q0, [&](std::size_t j) { out.push_back({i, static_cast<uint32_t>(j)}); });
        }
    }
}

void PairFinder::sweep(uint32_t objects, const CoordinateWords& words, PairList& out) {
    load_valid(objects, words);
    find_spans(choose_grid());
    cluster_by_first_cell();
    sort_by_min_x();
    bin();
    sweep_cells(unordered_);
    order(objects, unordered_, out);
}

void PairFinder::load_valid(uint32_t objects, const CoordinateWords& words) {
    valid_.clear();
    for (uint32_t i = 0; i < objects; ++i) {
        PackedBox box;
        read_box(words, i, box.bound);
        bool has_nan = false;
        for (float bound : box.bound) has_nan |= std::isnan(bound);
        if (has_nan) continue;  // every comparison with it is false: it meets nothing
        box.index = i;
        box.first_cell = 0;
        valid_.push_back(box);
    }
}

// Cells about twice the mean box extent, so that most boxes touch one or two
// cells per axis; none over kMaxCellsPerAxis a side or with fewer than
// kMinBoxesPerCell boxes on average.
PairFinder::Grid PairFinder::choose_grid() const {
    Grid grid;
    const std::size_t n = valid_.size();
    for (int axis = 0; axis < 2; ++axis) {
        double low = INFINITY, high = -INFINITY, extent = 0;
        std::size_t finite = 0;
        for (const PackedBox& box : valid_) {
            const float lo = box.bound[kMinY + axis], hi = box.bound[kMaxY + axis];
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
        grid.origin[axis] = low;
        grid.inverse_size[axis] = grid.cells[axis] / (high - low);
    }
    while (uint64_t{grid.cells[0]} * grid.cells[1] > std::max<uint64_t>(n / kMinBoxesPerCell, 1)) {
        // Coarsen the finer axis first.
        const int axis = grid.cells[0] >= grid.cells[1] ? 0 : 1;
        grid.inverse_size[axis] *= static_cast<double>((grid.cells[axis] + 1) / 2) / grid.cells[axis];
        grid.cells[axis] = (grid.cells[axis] + 1) / 2;
    }
    return grid;
}

// The cells of each box's y and z hulls [min(lo, hi), max(lo, hi)]: two boxes
// that meet on an axis have intersecting hulls even when inverted.
void PairFinder::find_spans(const Grid& chosen) {
    const std::size_t n = valid_.size();
    Grid grid = chosen;
    spans_.resize(n);
    for (int attempt = 0; attempt < 2; ++attempt) {
        entry_count_ = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const float* b = valid_[k].bound;
            spans_[k] = {grid.cell(0, std::min(b[kMinY], b[kMaxY])), grid.cell(0, std::max(b[kMinY], b[kMaxY])),
                         grid.cell(1, std::min(b[kMinZ], b[kMaxZ])), grid.cell(1, std::max(b[kMinZ], b[kMaxZ]))};
            entry_count_ += uint64_t{spans_[k].y1 - spans_[k].y0 + 1u} * (spans_[k].z1 - spans_[k].z0 + 1u);
        }
        if (entry_count_ <= kMaxEntriesPerBox * n) break;
        grid = Grid{};  // huge boxes everywhere: one cell
    }
    cells_y_ = grid.cells[0];
    cells_z_ = grid.cells[1];
}

// Boxes grouped by their first cell (a counting sort), so that the boxes of
// one cell lie close together when the cells are filled: index order says
// nothing about where a box is.
void PairFinder::cluster_by_first_cell() {
    const std::size_t n = valid_.size();
    cell_begin_.assign(std::size_t{cells_y_} * cells_z_ + 1, 0);
    auto first_cell = [&](const CellSpan& span) { return uint32_t{span.y0} * cells_z_ + span.z0; };
    for (const CellSpan& span : spans_) ++cell_begin_[first_cell(span) + 1];
    for (std::size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
    cell_next_.assign(cell_begin_.begin(), cell_begin_.end() - 1);
    clustered_.resize(n);
    items_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const uint32_t position = cell_next_[first_cell(spans_[k])]++;
        clustered_[position] = valid_[k];
        clustered_[position].first_cell = (uint32_t{spans_[k].y0} << 16) | spans_[k].z0;
        items_[position] = {ordered_key(valid_[k].bound[kMinX]), position, spans_[k]};
    }
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
// per cell), then one pass gathering the bounds.
void PairFinder::bin() {
    cell_begin_.assign(std::size_t{cells_y_} * cells_z_ + 1, 0);
    auto for_each_cell = [&](const CellSpan& span, auto&& visit) {
        for (uint32_t y = span.y0; y <= span.y1; ++y) {
            for (uint32_t z = span.z0; z <= span.z1; ++z) visit(y * cells_z_ + z);
        }
    };
    for (const SortItem& item : items_) for_each_cell(item.span, [&](uint32_t cell) { ++cell_begin_[cell + 1]; });
    for (std::size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
    cell_next_.assign(cell_begin_.begin(), cell_begin_.end() - 1);
    entry_box_.resize(entry_count_);
    for (const SortItem& item : items_) {
        for_each_cell(item.span, [&](uint32_t cell) { entry_box_[cell_next_[cell]++] = item.position; });
    }
    entries_.resize(entry_count_);
    entry_index_.assign(entry_count_ + kBlock, 0);
    entry_first_.assign(entry_count_ + kBlock, 0);
    for (uint32_t cell = 0; cell + 1 < cell_begin_.size(); ++cell) {
        const uint32_t y = cell / cells_z_, z = cell % cells_z_;
        for (uint32_t e = cell_begin_[cell]; e < cell_begin_[cell + 1]; ++e) {
            const PackedBox& box = clustered_[entry_box_[e]];
            entries_.set(e, box.bound);
            entry_index_[e] = box.index;
            entry_first_[e] = ((box.first_cell >> 16) == y ? 1u : 0u) | ((box.first_cell & 0xFFFF) == z ? 2u : 0u);
        }
    }
}

// Box pruning in each cell: box p meets only boxes q after it (min x order)
// with min_x(q) <= max_x(p), a prefix of the cell's rest; the block test does
// the six comparisons, so blocks running past the prefix add nothing. Both
// boxes are in this cell, so it is the first cell they share exactly when it
// is the first on y of one of them and the first on z of one of them.
void PairFinder::sweep_cells(PairList& unordered) const {
    const float* min_x = entries_.bound[kMinX].data();
    const uint32_t* index = entry_index_.data();
    const uint32_t* first = entry_first_.data();
    unordered.clear();
    for (uint32_t cell = 0; cell + 1 < cell_begin_.size(); ++cell) {
        const std::size_t end = cell_begin_[cell + 1];
        for (std::size_t p = cell_begin_[cell]; p < end; ++p) {
            float a[kCoordinates];
            entries_.get(p, a);
            const BlockTest test(entries_, a);
            const uint32_t i = index[p];
            for (std::size_t q0 = p + 1; q0 < end; q0 += kBlock) {
                uint32_t hits = test.hits(q0) & block_mask_before(q0, end);
                if (hits != 0) {
                    if ((first[p] & 1) == 0) hits &= block_flag_bits<0>(first, q0);
                    if ((first[p] & 2) == 0) hits &= block_flag_bits<1>(first, q0);
                    for_each_hit(hits, q0, [&](std::size_t q) {
                        const uint32_t j = index[q];
                        unordered.push_back({std::min(i, j), std::max(i, j)});
                    });
                }
                if (q0 + kBlock >= end || !(min_x[q0 + kBlock - 1] <= a[kMaxX])) break;
            }
        }
    }
}

// BoardCore's order: a counting sort on the first index, then each row by
// the second (rows are short, except in scenes where everything meets).
void PairFinder::order(uint32_t objects, const PairList& unordered, PairList& out) {
    row_start_.assign(std::size_t{objects} + 1, 0);
    for (const IndexPair& pair : unordered) ++row_start_[pair.first + 1];
    for (std::size_t r = 1; r < row_start_.size(); ++r) row_start_[r] += row_start_[r - 1];
    out.resize(unordered.size());
    row_next_.assign(row_start_.begin(), row_start_.end() - 1);
    for (const IndexPair& pair : unordered) out[row_next_[pair.first]++] = pair;
    for (uint32_t r = 0; r < objects; ++r) {
        auto begin = out.begin() + row_start_[r], end = out.begin() + row_start_[r + 1];
        if (end - begin < 2) continue;
        if (end - begin <= 16) {
            for (auto it = begin + 1; it != end; ++it) {  // insertion sort
                const IndexPair pair = *it;
                auto hole = it;
                for (; hole != begin && (hole - 1)->second > pair.second; --hole) *hole = *(hole - 1);
                *hole = pair;
            }
        } else {
            std::sort(begin, end, [](const IndexPair& a, const IndexPair& b) { return a.second < b.second; });
        }
    }
}

}  // namespace cdvp
