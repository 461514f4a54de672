// Configuration of the collision board: one struct per block, gathered here.
#pragma once

#include <cstdint>
#include <string>

#include "models/comparison_unit/comparison_unit.h"
#include "models/number_format/number_format.h"
#include "models/pair_collector/pair_collector.h"
#include "models/address_generator/tile_config.h"
#include "models/grid_binning/grid_config.h"
#include "models/grid_schedule/grid_slots.h"
#include "models/resources/resource_model.h"

namespace cdvp {

// What the board computes a sweep with (board.algorithm): the seed's
// all-pairs sweep over every box, or the grid board's binning pipeline in
// front of the same lanes (docs/grid_board.md). Chosen at construction, as
// the bitstream fixes it.
enum class BoardAlgorithm : uint8_t { kAllPairs, kGrid };

struct BoardConfig {
    // Parallelism: 2m-port coordinate memories (m block RAMs each), 2m-1 lanes.
    uint32_t m = 8;
    // Board clock in MHz. Default 66: the ADM-XRC-II's local bus clock tops out
    // at 66 MHz and a Virtex-II -4 float datapath is plausible there (assumption).
    double clock_mhz = 66.0;
    // The comparators' and coordinate memories' number format.
    NumberFormat format;
    ComparisonUnitConfig compare;
    PairCollectorConfig collector;
    // Block RAM (the seed's board) or SSRAM tiles (platform/memory_plan.h picks it).
    TileConfig tiles;
    // Banks of box memory: 1, the paper's board; 2 double-buffers the
    // coordinate memories (and the pair buffer), so that the host uploads
    // frame k+1 into one bank while the board sweeps frame k in the other,
    // and reads frame k's pairs back while frame k+1 sweeps
    // (docs/communication.md). Two banks cost twice the box memory.
    uint32_t box_banks = 1;
    static constexpr uint32_t kMaxBoxBanks = 2;
    BoardAlgorithm algorithm = BoardAlgorithm::kAllPairs;
    // The grid board's grid (algorithm kGrid only). Its boxes, cell lists
    // and pair buffer sit in SSRAM, whose timing `tiles` gives
    // (load_latency_cycles, cycles_per_box) with tiles.boxes = 0.
    GridConfig grid;

    static constexpr uint32_t kMaxM = (ComparisonUnit::kMaxLanes + 1) / 2;  // 32
    // Cycles of the collector stage: the FIFO write to the pair buffer write.
    static constexpr uint32_t kCollectorLatencyCycles = 1;

    uint32_t lanes() const { return 2 * m - 1; }
    bool grid_board() const { return algorithm == BoardAlgorithm::kGrid; }
    // The grid board's closed forms at this configuration (docs/grid_board.md).
    GridSlots grid_slots() const { return {lanes(), tiles.cycles_per_box, tiles.load_latency_cycles}; }
    // L: block RAM read + compare pipeline + collector stage. A sweep takes
    // S(N,m) + L + stall cycles from start to done.
    uint32_t pipeline_latency() const;
    // What a board of this configuration is, so that no caller reaches into
    // its blocks: the address generator's slots for N boxes (S(N,m) on a
    // board in block RAM, the tiled schedule's slots on one in SSRAM:
    // SweepSchedule; a grid board's depend on the boxes, so its worst case,
    // worst_grid_slots, bounds them); the block RAM primitives of the coordinate memories
    // for `capacity` boxes (G x m x ceil(N/D) a bank, times box_banks), or
    // of the tile buffers (G x (2m+2) x ceil(min(T,N)/D)), G primitives side
    // by side for the six coordinates and D boxes a primitive in the number
    // format's cheapest block RAM layout (NumberFormat::block_ram_layout;
    // float32: 6 and 512); and the bytes of block RAM words the clocked
    // model keeps for them (the bank being swept); a grid board's are its
    // double-buffered cell buffer's (G x 2m x ceil(C/D)).
    uint64_t sweep_cycles(uint64_t objects) const;
    // The most slots a sweep of `objects` boxes can take, whatever the boxes:
    // sweep_cycles(), or a grid board's worst case.
    uint64_t worst_sweep_slots(uint64_t objects) const;
    // The slots a sweep of `objects` boxes took, from the cycles and stalls
    // its counters showed: sweep_cycles(), or on a grid board, whose slots
    // depend on its boxes, the cycles less the pipeline's latency and stalls.
    uint64_t swept_slots(uint64_t objects, uint64_t cycles, uint64_t stalls) const {
        return grid_board() ? cycles - pipeline_latency() - stalls : sweep_cycles(objects);
    }
    // The runs a row's pairs may come in over a sweep (the pair formats'
    // worst case): one in block RAM, one a column tile when tiled, any
    // number on a grid board (0).
    uint64_t row_pieces(uint32_t objects) const { return grid_board() ? 0 : tiles.row_pieces(objects); }
    uint64_t block_rams(uint64_t capacity) const { return block_ram_geometry(capacity).block_rams(); }
    // How those primitives are arranged, and so which of them a cycle
    // enables: G word groups, ceil(depth/D) deep, memory_copies() a bank
    // (grid: cell_buffer_copies()), block_ram_banks() banks.
    BlockRamGeometry block_ram_geometry(uint64_t capacity) const;
    uint64_t block_ram_bytes(uint64_t capacity) const;
    // Boxes each coordinate memory holds: all `capacity`, or one tile.
    uint64_t memory_depth(uint64_t capacity) const;
    // The grid board's cell buffer: boxes deep, copies (two halves of m).
    uint64_t cell_buffer_copies() const { return 2ull * m; }
    // Copies of each coordinate memory in a bank: m (2m ports); tiled, a double-buffered
    // 2m-port column memory and a double-buffered row memory for port 0: 2m + 2.
    uint64_t memory_copies() const { return tiles.tiled() ? 2ull * m + 2 : m; }
    // Banks of those copies in block RAM: box_banks, or 1 on a tiled board
    // (it keeps its banks in SSRAM; its tile buffers stay as they are).
    uint64_t block_ram_banks() const { return tiles.tiled() ? 1 : box_banks; }
    // Clock period in picoseconds (the simulation's time resolution).
    double period_ps() const { return 1e6 / clock_mhz; }
    // Throws std::invalid_argument with one line "SETTING: expected ..., got ...",
    // SETTING named as in the run report's config.
    void validate() const;
};

}  // namespace cdvp
