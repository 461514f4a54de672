#include "models/rtl_engine/rtl_variant.h"

#include <deque>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "models/rtl_engine/rtl_model_cache.h"

namespace cdvp {

std::string RtlVariant::spec() const {
    std::ostringstream s;
    s << "m=" << m << ",format=" << format().name()
      << ",latency=" << compare_latency << ",fifo=" << fifo_depth << ",buffer=" << buffer_depth
      << ",tile=" << tile_boxes << ",tile_latency=" << tile_latency << ",capacity=" << capacity();
    return s.str();
}

std::string RtlVariant::name() const {
    std::ostringstream s;
    s << 'm' << m << '_' << format().name() << "_l" << compare_latency << "_f" << fifo_depth << "_b" << buffer_depth
      << "_t" << tile_boxes << "_s" << tile_latency << "_a" << address_bits;
    return s.str();
}

std::vector<std::string> RtlVariant::verilator_parameters() const {
    const bool is_float = format_bits == 0;
    auto parameter = [](const char* name, uint64_t value) { return std::string("-G") + name + "=" + std::to_string(value); };
    return {parameter("M", m),
            parameter("AW", address_bits),
            parameter("FLOAT", is_float ? 1 : 0),
            parameter("WIDTH", is_float ? 32 : format_bits),
            parameter("COMPARE_LATENCY", compare_latency),
            parameter("FIFO_DEPTH", fifo_depth),
            parameter("BUFFER_DEPTH", buffer_depth),
            parameter("TILE_BOXES", tile_boxes),
            parameter("TILE_LATENCY", tile_latency)};
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
        return "the grid board (board.algorithm grid) has no RTL top: only its binning sequencer, cell function, "
               "one-cell filter, cell loader and cell buffer are RTL, tested block by block; run it at the cycle, fast "
               "or analytic level";
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

namespace {
// The variants compiled on first use (or loaded from the cache) by this
// process: each once, kept, since their models live in shared objects that
// stay loaded.
const BuiltRtlVariant& compiled_rtl_variant(const RtlVariant& variant) {
    static std::mutex mutex;
    static std::deque<BuiltRtlVariant> compiled;
    const std::lock_guard<std::mutex> lock(mutex);
    for (const BuiltRtlVariant& built : compiled) {
        if (built.variant.spec() == variant.spec()) return built;
    }
    const RtlBoardMaker maker = process_rtl_model_cache().load(variant);
    const RtlMemoryShape shape = variant.memory();
    return compiled.emplace_back(
        BuiltRtlVariant{variant, [maker, shape] { return std::unique_ptr<RtlBoard>(maker(&shape)); }});
}
}  // namespace

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
    return compiled_rtl_variant(RtlVariant::for_board(config, capacity));
}

}  // namespace cdvp
