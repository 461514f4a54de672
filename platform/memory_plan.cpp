#include "platform/memory_plan.h"

#include <algorithm>

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

MemoryPlan plan_memory(const Settings& settings, uint64_t capacity) {
    const DeviceSettings& device = settings.device;
    MemoryPlan plan;
    plan.tiles = ssram_tiles(device);  // boxes = 0 until SSRAM serves
    plan.ssram_capacity = device.ssram_banks == 0 ? 0 : device.ssram_words / plan.tiles.cycles_per_box;
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
        board.tiles = plan.tiles;
        if (plan.tile_fits && board.block_rams(capacity) <= settings.device.block_rams) return m;
    }
    return 0;
}

BoardConfig planned_board(const Settings& settings, uint64_t capacity) {
    BoardConfig board = settings.board;
    board.tiles = plan_memory(settings, capacity).tiles;
    return board;
}

}  // namespace cdvp
