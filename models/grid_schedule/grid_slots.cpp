#include "models/grid_schedule/grid_slots.h"

namespace cdvp {

uint64_t worst_grid_slots(uint64_t objects, const GridConfig& grid, const GridSlots& slots) {
    if (objects < 2) return 0;
    const uint64_t n = objects, k = grid.max_span, c = grid.cell_capacity, w = slots.lanes;
    const uint64_t q = slots.cycles_per_box, fill = 2ull * slots.latency + GridConfig::kCellFunctionSlots;
    uint64_t total = slots.bounds(n) + GridSlots::setup() + 2 * slots.pass(n * std::max(q, k)) + grid.cells_for(n);
    // Cells: at most n k entries in cells of at most c boxes; S(n) <= n ceil(c / w) for n <= c.
    total += n * k * ((c + w - 1) / w + q + fill);
    // Large: at most ceil(n / c) tiles; each box streams past each tile in
    // q slots or one a w columns, and the columns of all tiles sum to at
    // most n^2 / 2 (a large box meets only the tiles' boxes after it).
    const uint64_t tiles = (n + c - 1) / c;
    total += n * q + tiles * (fill + slots.latency) + tiles * n * (q + 1) + n * n / (2 * w);
    return total;
}

}  // namespace cdvp
