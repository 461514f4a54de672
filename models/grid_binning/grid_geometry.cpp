#include "models/grid_binning/grid_geometry.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cdvp {

namespace {
constexpr uint32_t kMinusInfinityWord = 0xFF80'0000u;
constexpr uint32_t kPlusInfinityWord = 0x7F80'0000u;
}  // namespace

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
