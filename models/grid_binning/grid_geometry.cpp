#include "models/grid_binning/grid_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cdvp {

namespace {
constexpr uint32_t kMinusInfinityWord = 0xFF80'0000u;
constexpr uint32_t kPlusInfinityWord = 0x7F80'0000u;

// GridGeometry::cell_of_value without branches, so that a loop of them
// vectorizes: the position clamped before it is converted.
inline uint32_t cell_of_position(float position, float dims_value, uint32_t dims) {
    const float inside = position > 0.0f && position < dims_value ? position : 0.0f;
    const auto cell = static_cast<uint32_t>(static_cast<int32_t>(inside));
    return position >= dims_value ? dims - 1 : cell;
}

// One float32 bound over a run: NumberFormat::key, excluded and
// GridGeometry::cell written out for the vectorizer, in each width the CPU
// may have (function multiversioning picks one when the program loads).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void float32_bound_cells(const uint32_t* words, uint32_t n, GridAxis axis, uint32_t dims, uint32_t minus_infinity,
                         uint32_t plus_infinity, uint32_t* keys, uint32_t* cells, uint32_t* excluded) {
    const auto dims_value = static_cast<float>(dims);
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t word = words[k];
        excluded[k] |= static_cast<uint32_t>((word & 0x7FFF'FFFFu) > 0x7F80'0000u);
        const uint32_t key = NumberFormat::float32().key(word);
        keys[k] = key;
        const float position = (NumberFormat::float32_value(key) - axis.lo) * axis.scale;
        uint32_t cell = cell_of_position(position, dims_value, dims);
        cell = key <= minus_infinity ? 0 : cell;
        cells[k] = key >= plus_infinity ? dims - 1 : cell;
    }
}

// The same for a fixed-point format: no infinities, nothing excluded.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void fixed_bound_cells(const uint32_t* words, uint32_t n, uint32_t mask, GridAxis axis, uint32_t dims, uint32_t* keys,
                       uint32_t* cells) {
    const auto dims_value = static_cast<float>(dims);
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t key = words[k] & mask;
        keys[k] = key;
        cells[k] = cell_of_position((NumberFormat::fixed_value(key) - axis.lo) * axis.scale, dims_value, dims);
    }
}

// One axis's box centres over a run, float32: the centre of the bounds'
// values as keys give them (NumberFormat::approximate of key), and whether
// either word is a NaN.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void float32_centres(const uint32_t* lo_words, const uint32_t* hi_words, uint32_t n, float* centres,
                     uint32_t* excluded) {
    const NumberFormat format = NumberFormat::float32();
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t lo = lo_words[k], hi = hi_words[k];
        excluded[k] |= static_cast<uint32_t>((lo & 0x7FFF'FFFFu) > 0x7F80'0000u) |
                       static_cast<uint32_t>((hi & 0x7FFF'FFFFu) > 0x7F80'0000u);
        centres[k] = GridBounds::centre_of(NumberFormat::float32_value(format.key(lo)),
                                           NumberFormat::float32_value(format.key(hi)));
    }
}

// The same for a fixed-point format: nothing excluded.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void fixed_centres(const uint32_t* lo_words, const uint32_t* hi_words, uint32_t n, uint32_t mask, float* centres) {
    for (uint32_t k = 0; k < n; ++k) {
        centres[k] = GridBounds::centre_of(NumberFormat::fixed_value(lo_words[k] & mask),
                                           NumberFormat::fixed_value(hi_words[k] & mask));
    }
}

}  // namespace

void GridBounds::add_run(const uint32_t* const* words, uint32_t begin, uint32_t n) {
    float centres[3][BoundRun::kBoxes];
    uint32_t excluded[BoundRun::kBoxes] = {};
    for (uint32_t a = 0; a < 3; ++a) {
        if (format_.is_float()) {
            float32_centres(words[a] + begin, words[a + 3] + begin, n, centres[a], excluded);
        } else {
            fixed_centres(words[a] + begin, words[a + 3] + begin, n, format_.word_mask(), centres[a]);
        }
    }
    // In box order, as add() takes them.
    for (uint32_t k = 0; k < n; ++k) {
        if (excluded[k] != 0) continue;
        for (uint32_t a = 0; a < 3; ++a) take(a, centres[a][k]);
    }
}

void GridGeometry::fill_run(const uint32_t* const* words, uint32_t begin, uint32_t n, BoundRun& run) const {
    std::fill(run.excluded, run.excluded + n, 0u);
    for (uint32_t c = 0; c < 6; ++c) {
        const GridAxis& axis = axes_[c % 3];
        if (format_.is_float()) {
            float32_bound_cells(words[c] + begin, n, axis, dims_, minus_infinity_, plus_infinity_, run.key[c],
                                run.cell[c], run.excluded);
        } else {
            fixed_bound_cells(words[c] + begin, n, format_.word_mask(), axis, dims_, run.key[c], run.cell[c]);
        }
    }
}

uint32_t GridConfig::dims_for(uint64_t objects) const {
    if (dims != 0) return dims;
    uint32_t g = 1;
    while (g < kMaxDims && kBoxesPerCell * uint64_t{g + 1} * (g + 1) * (g + 1) <= objects) ++g;
    return g;
}

void GridConfig::validate() const {
    if (dims > kMaxDims) {
        throw std::invalid_argument("grid.dims: expected 0 (auto) or 1 to " + std::to_string(kMaxDims) +
                                    " cells a side, got " + std::to_string(dims));
    }
    if (!(cell_size >= 0.0f) || !std::isfinite(cell_size)) {
        throw std::invalid_argument("grid.cell_size: expected 0 (fitted) or a finite positive size, got " +
                                    std::to_string(cell_size));
    }
    if (cell_capacity < kMinCellCapacity || cell_capacity > kMaxCellCapacity) {
        throw std::invalid_argument("grid.cell_capacity: expected " + std::to_string(kMinCellCapacity) + " to " +
                                    std::to_string(kMaxCellCapacity) + " boxes, got " + std::to_string(cell_capacity));
    }
    if (max_span < 1 || max_span > kMaxSpan) {
        throw std::invalid_argument("grid.max_span: expected 1 to " + std::to_string(kMaxSpan) + " cells, got " +
                                    std::to_string(max_span));
    }
}

GridGeometry::GridGeometry(NumberFormat format, uint32_t dims, const std::array<GridAxis, 3>& axes)
    : format_(format), dims_(dims), axes_(axes) {
    infinities_ = format.is_float();
    if (infinities_) {
        minus_infinity_ = format.key(kMinusInfinityWord);
        plus_infinity_ = format.key(kPlusInfinityWord);
    }
}

GridGeometry GridBounds::geometry(const GridConfig& config, uint32_t dims) const {
    std::array<GridAxis, 3> axes{};
    for (uint32_t a = 0; a < 3; ++a) {
        if (least_[a] > greatest_[a]) continue;  // no finite centre: every finite value in cell 0
        axes[a].lo = least_[a];
        if (config.cell_size > 0.0f) {
            axes[a].scale = 1.0f / config.cell_size;
            continue;
        }
        const float extent = greatest_[a] - least_[a];
        // An extent that overflows float32 leaves the scale 0: one cell, still exact.
        if (extent > 0.0f && std::isfinite(extent)) axes[a].scale = static_cast<float>(dims) / extent;
    }
    return GridGeometry(format_, dims, axes);
}

}  // namespace cdvp
