#include "models/board_spec/board_config.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "models/address_generator/address_generator.h"
#include "models/address_generator/sweep_schedule.h"
#include "models/block_ram/block_ram.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"

namespace cdvp {

uint64_t BoardConfig::sweep_cycles(uint64_t objects) const {
    if (!tiles.tiled()) return AddressGenerator::sweep_cycles(objects, m);
    return SweepSchedule(m, tiles, static_cast<uint32_t>(objects)).slots();
}

uint64_t BoardConfig::worst_sweep_slots(uint64_t objects) const {
    return grid_board() ? worst_grid_slots(objects, grid, grid_slots()) : sweep_cycles(objects);
}

uint64_t BoardConfig::memory_depth(uint64_t capacity) const {
    return tiles.tiled() ? std::min<uint64_t>(tiles.boxes, capacity) : capacity;
}

BlockRamGeometry BoardConfig::block_ram_geometry(uint64_t capacity) const {
    const uint64_t depth = grid_board() ? grid.cell_capacity : memory_depth(capacity);
    const BlockRamLayout layout = format.block_ram_layout(depth);
    BlockRamGeometry g;
    g.word_groups = layout.word_groups();
    g.depth_blocks = (depth + layout.depth - 1) / layout.depth;
    // The lanes' enable reaches both tile buffers and both cell buffer
    // halves (their outputs are chosen after the read), one bank of boxes.
    g.copies = grid_board() ? cell_buffer_copies() : memory_copies();
    g.banks = grid_board() ? 1 : block_ram_banks();
    // A tiled or grid board's boxes sit in SSRAM: its loader, not the upload, writes its block RAMs.
    g.uploaded = !grid_board() && !tiles.tiled();
    return g;
}

uint64_t BoardConfig::block_ram_bytes(uint64_t capacity) const {
    // The model keeps each coordinate's words apart (packing changes the count
    // of primitives, not the words): six columns of whole primitives a copy,
    // for the bank being swept (the host's bank is the board's store).
    const uint64_t depth = grid_board() ? grid.cell_capacity : memory_depth(capacity);
    const BlockRamLayout layout = format.block_ram_layout(depth);
    const uint64_t cascaded = (depth + layout.depth - 1) / layout.depth;
    const uint64_t copies = grid_board() ? cell_buffer_copies() : memory_copies();
    return copies * kCoordinates * cascaded * layout.depth * sizeof(uint32_t);
}

uint32_t BoardConfig::pipeline_latency() const {
    return BlockRam::kReadLatencyCycles + compare.latency_cycles + kCollectorLatencyCycles;
}

namespace {
void require(bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
}
}  // namespace

void BoardConfig::validate() const {
    std::ostringstream clock;
    clock << clock_mhz;
    require(m >= 1 && m <= kMaxM, "m: expected 1 to " + std::to_string(kMaxM) +
                                      " (2m-1 lanes, at most 63), got " + std::to_string(m));
    require(std::isfinite(clock_mhz) && clock_mhz >= 1.0 && clock_mhz <= 10000.0,
            "clock_mhz: expected 1 to 10000 MHz, got " + clock.str());
    require(compare.latency_cycles <= 64,
            "compare_latency_cycles: expected at most 64 cycles, got " + std::to_string(compare.latency_cycles));
    require(collector.fifo_depth >= lanes() && collector.fifo_depth <= (1u << 20),
            "fifo_depth: expected 2m-1 = " + std::to_string(lanes()) +
                " (one cycle's hits) to 1048576 pairs, got " + std::to_string(collector.fifo_depth));
    require(collector.drain_per_cycle >= 1 && collector.drain_per_cycle <= 64,
            "drain_per_cycle: expected 1 to 64 pairs a cycle, got " + std::to_string(collector.drain_per_cycle));
    require(collector.buffer_depth >= 1 && collector.buffer_depth <= address_map::kMaxBufferedPairs,
            "pair_buffer_depth: expected 1 to " + std::to_string(address_map::kMaxBufferedPairs) +
                " pairs, got " + std::to_string(collector.buffer_depth));
    require(box_banks >= 1 && box_banks <= kMaxBoxBanks,
            "box_banks: expected 1 or 2 banks of box memory, got " + std::to_string(box_banks));
    require(tiles.load_latency_cycles <= 64,
            "ssram_latency_cycles: expected at most 64 cycles, got " + std::to_string(tiles.load_latency_cycles));
    require(tiles.cycles_per_box >= 1 && tiles.cycles_per_box <= kCoordinates,
            "ssram cycles a box: expected 1 to 6, got " + std::to_string(tiles.cycles_per_box));
    if (grid_board()) {
        grid.validate();
        require(!tiles.tiled(), "tile_boxes: a grid board keeps its boxes in SSRAM untiled, got tiles of " +
                                    std::to_string(tiles.boxes));
    }
}

}  // namespace cdvp
