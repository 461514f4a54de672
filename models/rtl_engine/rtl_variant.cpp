#include "models/rtl_engine/rtl_variant.h"

#include <sstream>
#include <stdexcept>

namespace cdvp {

std::string RtlVariant::spec() const {
    std::ostringstream s;
    s << "m=" << m << ",format=" << format().name()
      << ",latency=" << compare_latency << ",fifo=" << fifo_depth << ",buffer=" << buffer_depth
      << ",tile=" << tile_boxes << ",tile_latency=" << tile_latency << ",capacity=" << capacity();
    return s.str();
}

RtlVariant RtlVariant::for_board(const BoardConfig& config, uint32_t capacity) {
    RtlVariant v;
    v.m = config.m;
    v.format_bits = config.format.is_float() ? 0 : config.format.bits();
    v.compare_latency = config.compare.latency_cycles;
    v.fifo_depth = config.collector.fifo_depth;
    v.buffer_depth = config.collector.buffer_depth;
    v.tile_boxes = config.tiles.boxes;
    v.tile_latency = config.tiles.tiled() ? config.tiles.load_latency_cycles : 2;
    v.address_bits = 4;
    while (v.capacity() < capacity) ++v.address_bits;
    return v;
}

BoardConfig RtlVariant::board() const {
    BoardConfig config;
    config.m = m;
    config.format = format();
    config.compare.latency_cycles = compare_latency;
    config.collector.fifo_depth = fifo_depth;
    config.collector.buffer_depth = buffer_depth;
    config.collector.drain_per_cycle = 1;
    config.tiles.boxes = tile_boxes;
    config.tiles.load_latency_cycles = tile_latency;
    config.tiles.cycles_per_box = 1;
    return config;
}

bool RtlVariant::serves(const BoardConfig& config, uint32_t boxes) const {
    const RtlVariant need = for_board(config, boxes);
    return m == need.m && format_bits == need.format_bits && compare_latency == need.compare_latency &&
           fifo_depth == need.fifo_depth && buffer_depth == need.buffer_depth && tile_boxes == need.tile_boxes &&
           (tile_boxes == 0 || tile_latency == need.tile_latency) && capacity() >= boxes;
}

std::string rtl_unsupported(const BoardConfig& config) {
    if (config.grid_board()) {
        return "the board RTL is the all-pairs board's; the grid board (board.algorithm grid) runs on the cycle or "
               "fast engine";
    }
    if (config.box_banks != 1) {
        return "the board RTL has one box bank (pipelined frames run on the cycle or fast engine); box_banks is " +
               std::to_string(config.box_banks);
    }
    if (config.collector.drain_per_cycle != 1) {
        return "the board RTL moves one pair a cycle into the pair buffer; drain_per_cycle is " +
               std::to_string(config.collector.drain_per_cycle);
    }
    if (config.tiles.tiled() && config.tiles.cycles_per_box != 1) {
        return "the board RTL reads a box from its six SSRAM banks in one cycle; cycles_per_box is " +
               std::to_string(config.tiles.cycles_per_box);
    }
    return {};
}

const BuiltRtlVariant& rtl_variant_for(const BoardConfig& config, uint32_t capacity) {
    if (const std::string why = rtl_unsupported(config); !why.empty()) {
        throw std::invalid_argument("fidelity rtl: " + why);
    }
    const BuiltRtlVariant* best = nullptr;
    for (const BuiltRtlVariant& built : built_rtl_variants()) {
        if (built.variant.serves(config, capacity) &&
            (best == nullptr || built.variant.address_bits < best->variant.address_bits)) {
            best = &built;
        }
    }
    if (best != nullptr) return *best;
    const std::size_t count = built_rtl_variants().size();
    throw std::invalid_argument("fidelity rtl: no Verilator build of the board RTL serves this board (" +
                                std::to_string(count) + " built); add '" +
                                RtlVariant::for_board(config, capacity).spec() +
                                "' to CDVP_RTL_VARIANTS and rebuild (docs/rtl.md; cdvp rtl-variants lists them)");
}

}  // namespace cdvp
