#include "platform/memory_plan.h"

#include <algorithm>

#include "models/common/user_text.h"

namespace cdvp {

namespace {

BoardConfig tiled(const BoardConfig& board, uint64_t tile_boxes) {
    BoardConfig b = board;
    b.tiles.boxes = static_cast<uint32_t>(tile_boxes);
    return b;
}

TileConfig ssram_tiles(const DeviceSettings& device) {
    TileConfig tiles;
    tiles.load_latency_cycles = device.ssram_latency_cycles;
    // One coordinate a bank: with six banks a box a cycle, with fewer the
    // banks take turns.
    tiles.cycles_per_box =
        device.ssram_banks == 0 ? 1 : (kCoordinates + device.ssram_banks - 1) / device.ssram_banks;
    return tiles;
}

}  // namespace

uint32_t largest_tile(const BoardConfig& board, uint64_t capacity, uint64_t block_rams) {
    // Block RAMs grow with the tile (BoardConfig::block_rams, whatever a
    // primitive holds): the largest fitting tile by bisection.
    const uint64_t most = std::max<uint64_t>(capacity, 1);
    if (block_rams == 0) return static_cast<uint32_t>(most);
    if (tiled(board, 1).block_rams(1) > block_rams) return 0;
    uint64_t lo = 1, hi = most;
    while (lo < hi) {
        const uint64_t mid = lo + (hi - lo + 1) / 2;
        if (tiled(board, mid).block_rams(mid) <= block_rams) lo = mid;
        else hi = mid - 1;
    }
    return static_cast<uint32_t>(lo);
}

GridMemory plan_grid_memory(const Settings& settings, uint64_t capacity) {
    GridMemory grid;
    const DeviceSettings& device = settings.device;
    const uint64_t cells = settings.board.grid.cells_for(capacity);
    grid.words = uint64_t{device.ssram_banks} * device.ssram_words;
    grid.fixed_words = kCoordinates * capacity + 3 * cells + capacity + 2ull * settings.board.collector.buffer_depth;
    if (settings.run.ignore_capacity) return grid;  // entries unbounded
    grid.fits = grid.fixed_words <= grid.words;
    grid.entries = grid.fits ? grid.words - grid.fixed_words : 0;
    return grid;
}

MemoryPlan plan_memory(const Settings& settings, uint64_t capacity) {
    const DeviceSettings& device = settings.device;
    MemoryPlan plan;
    plan.tiles = ssram_tiles(device);  // boxes = 0 until SSRAM serves
    plan.ssram_capacity = device.ssram_banks == 0 ? 0 : device.ssram_words / plan.tiles.cycles_per_box;
    if (settings.board.grid_board()) {
        // Its boxes always sit in SSRAM, untiled: the cell buffer is its only block RAM.
        plan.grid = plan_grid_memory(settings, capacity);
        return plan;
    }
    const uint32_t fitting = largest_tile(settings.board, capacity, device.block_rams);
    const BoxMemory asked = settings.memory.memory;
    if (asked == BoxMemory::kBlockRam) return plan;
    if (asked == BoxMemory::kAuto) {
        const bool in_block_ram = device.block_rams == 0 || settings.run.ignore_capacity ||
                                  settings.board.block_rams(capacity) <= device.block_rams;
        if (in_block_ram || fitting == 0) return plan;
    }
    plan.ssram = true;
    uint64_t tile = settings.memory.tile_boxes;
    if (tile == 0) {
        tile = fitting;
        plan.tile_fits = fitting != 0;
        // None fits: a tile as deep as one primitive, costed (and refused) as such.
        if (fitting == 0) tile = largest_tile(settings.board, capacity, tiled(settings.board, 1).block_rams(1));
    } else {
        plan.tile_fits = device.block_rams == 0 || tiled(settings.board, tile).block_rams(capacity) <= device.block_rams;
    }
    plan.tiles.boxes = static_cast<uint32_t>(std::max<uint64_t>(tile, 1));
    return plan;
}

uint32_t largest_m_in_block_rams(Settings settings, uint64_t capacity) {
    for (uint32_t m = BoardConfig::kMaxM; m >= 1; --m) {
        settings.board.m = m;
        const MemoryPlan plan = plan_memory(settings, capacity);
        BoardConfig board = settings.board;
        plan.apply(board);
        if (plan.tile_fits && board.block_rams(capacity) <= settings.device.block_rams) return m;
    }
    return 0;
}

BoardConfig planned_board(const Settings& settings, uint64_t capacity) {
    BoardConfig board = settings.board;
    plan_memory(settings, capacity).apply(board);
    return board;
}

}  // namespace cdvp

namespace cdvp {

void check_grid_fits(const SettingValues& values, uint64_t objects, const std::string& objects_text) {
    const Settings& settings = values.settings();
    if (!settings.board.grid_board() || settings.run.ignore_capacity) return;
    const std::string explore = "; " + values.names().setting_to(*find_setting("run.ignore_capacity"), "yes") +
                                " runs it anyway";
    const DeviceSettings& device = settings.device;
    const BoardConfig board = planned_board(settings, objects);
    const uint64_t block_rams = board.block_rams(objects);
    if (device.block_rams != 0 && block_rams > device.block_rams) {
        const BlockRamLayout layout = board.format.block_ram_layout(board.grid.cell_capacity);
        throw InputError(values.where(*find_setting("device.block_rams")) + ": " + std::to_string(device.block_rams) +
                         " block RAMs are too few for the grid board's cell buffer at " +
                         values.value_and_origin(*find_setting("board.m")) + " and " +
                         values.value_and_origin(*find_setting("board.grid.cell_capacity")) + ": it needs " +
                         std::to_string(layout.word_groups()) + " x 2m x ceil(C/" + std::to_string(layout.depth) +
                         ") = " + std::to_string(block_rams) + explore);
    }
    const GridMemory grid = plan_grid_memory(settings, objects);
    if (device.ssram_banks == 0) {
        throw InputError(values.where(*find_setting("device.ssram_banks")) +
                         ": the device has no off-chip SSRAM (0 banks); the grid board keeps its boxes and cell "
                         "lists there" + explore);
    }
    const uint64_t dims = settings.board.grid.dims;
    const uint64_t count_table = 3 * settings.board.grid.cells_for(objects);
    const uint64_t others = grid.fixed_words - count_table;  // boxes, large list, pair buffer
    if (!grid.fits && dims != 0 && count_table > others) {
        // The grid's own size is what does not fit: name it, and the largest that would.
        uint64_t largest = 0;
        while (largest < dims && others + 3 * (largest + 1) * (largest + 1) * (largest + 1) <= grid.words) ++largest;
        throw InputError(values.where(*find_setting("board.grid.dims")) + ": a grid of " + std::to_string(dims) +
                         "^3 cells needs a count table of 3G^3 = " + std::to_string(count_table) +
                         " words, which with the " + std::to_string(others) +
                         " words of the boxes, large list and pair buffer at " + objects_text + " is more than the " +
                         std::to_string(grid.words) +
                         " words of SSRAM (" + values.value_and_origin(*find_setting("device.ssram_banks")) + " of " +
                         values.value_and_origin(*find_setting("device.ssram_words")) + "); expected " +
                         (largest == 0 ? std::string("0 (fitted to each frame)")
                                       : "at most " + std::to_string(largest) + " cells a side, or 0 (fitted)") +
                         explore);
    }
    if (!grid.fits) {
        throw InputError(values.where(*find_setting("device.ssram_words")) + ": " + std::to_string(device.ssram_words) +
                         " words a bank in " + std::to_string(device.ssram_banks) + " SSRAM banks (" +
                         std::to_string(grid.words) + " words) are too few for the grid board at " + objects_text +
                         ": its boxes, count table, large list and pair buffer (" +
                         values.value_and_origin(*find_setting("board.pair_buffer_depth")) +
                         ") need 6N + 3G^3 + N + 2P = " + std::to_string(grid.fixed_words) +
                         " words before any cell entry: use fewer objects or a smaller pair buffer" + explore);
    }
}

}  // namespace cdvp
