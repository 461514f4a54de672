// Where a run's board keeps its boxes: block RAM, or off-chip SSRAM swept in
// tiles (board.memory, board.tile_boxes and the device's block RAMs and SSRAM).
#pragma once

#include <cstdint>
#include <string>

#include "models/board_spec/board_config.h"
#include "platform/settings/setting_values.h"
#include "platform/settings/settings.h"

namespace cdvp {

// A grid board's SSRAM (docs/grid_board.md, "Memory"): its boxes (6N
// words), count table and busy-cell list (3 G^3), large list (N) and pair
// buffer (2 words a pair) must fit; the cell entries take what is left.
struct GridMemory {
    uint64_t words = 0;          // banks x words a bank
    uint64_t fixed_words = 0;    // everything but the entries
    uint64_t entries = GridConfig::kUnboundedEntries;
    bool fits = true;
};

struct MemoryPlan {
    bool ssram = false;  // the boxes sit in SSRAM swept in tiles (the seed's board)
    TileConfig tiles;  // tiles.boxes = 0 on a board in block RAM
    uint64_t ssram_capacity = 0;  // boxes the SSRAM holds (0: no SSRAM)
    bool tile_fits = true;        // the tile buffers fit the device's block RAMs
    GridMemory grid;              // a grid board's SSRAM

    // The plan on a board: its tiles (a grid board: its SSRAM's timing) and
    // a grid board's entry capacity.
    void apply(BoardConfig& board) const {
        board.tiles = tiles;
        board.grid.entry_capacity = grid.entries;
    }
};

// For boards of `capacity` boxes. block_ram and ssram are taken as asked;
// auto picks block RAM when the coordinate memories fit the device's block
// RAMs (or run.ignore_capacity is yes), else SSRAM when some tile fits, else
// block RAM (which the run then refuses, naming the block RAMs). A tile of 0
// boxes asks for the largest whose buffers fit the device; when none does,
// the plan keeps a one-primitive tile and tile_fits is false.
MemoryPlan plan_memory(const Settings& settings, uint64_t capacity);
// The largest m (1 to BoardConfig::kMaxM) whose coordinate memories or tile
// buffers, in the memory plan_memory picks at that m, fit the device's block
// RAMs; 0 when none does.
uint32_t largest_m_in_block_rams(Settings settings, uint64_t capacity);
// settings.board with the plan applied.
BoardConfig planned_board(const Settings& settings, uint64_t capacity);
// A grid board of `capacity` boxes in the device's SSRAM; unbounded with
// run.ignore_capacity (a larger memory explored).
GridMemory plan_grid_memory(const Settings& settings, uint64_t capacity);
// A grid board of `objects` boxes (`objects_text` names them as a refusal
// does): its cell buffer must fit the device's block RAMs and its boxes,
// tables and pair buffer its SSRAM. Nothing is checked with
// run.ignore_capacity. Throws InputError naming the settings.
void check_grid_fits(const SettingValues& values, uint64_t objects, const std::string& objects_text);
// The largest tile (at most `capacity` boxes) whose buffers fit `block_rams`
// block RAMs at the board's m; 0 when not even one box a tile fits.
uint32_t largest_tile(const BoardConfig& board, uint64_t capacity, uint64_t block_rams);

}  // namespace cdvp
