#include "models/rtl_engine/rtl_variant.h"

#include <algorithm>
#include <cstring>
#include <deque>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "models/rtl_engine/rtl_model_cache.h"

namespace cdvp {

namespace {
// The grid top's limits: the sequencer's read-ahead FIFO and the cell
// loader's slot counter (grid_sequencer.v, cell_loader.v), and the count
// table's register file kept to a size Verilator builds in seconds.
constexpr uint32_t kGridRtlMaxLatency = 8;
constexpr uint64_t kGridRtlMaxCells = uint64_t{1} << 18;
}  // namespace

std::string RtlVariant::spec() const {
    std::ostringstream s;
    s << "m=" << m << ",format=" << format().name()
      << ",latency=" << compare_latency << ",fifo=" << fifo_depth << ",buffer=" << buffer_depth
      << ",tile=" << tile_boxes << ",tile_latency=" << tile_latency << ",capacity=" << capacity();
    if (grid) {
        s << ",algorithm=grid,dims=" << grid_dims << ",cell_size=" << cell_size_bits << ",cell_capacity=" << cell_capacity
          << ",max_span=" << max_span << ",entries=" << entry_capacity;
    }
    return s.str();
}

std::string RtlVariant::name() const {
    std::ostringstream s;
    s << 'm' << m << '_' << format().name() << "_l" << compare_latency << "_f" << fifo_depth << "_b" << buffer_depth
      << "_t" << tile_boxes << "_s" << tile_latency << "_a" << address_bits;
    if (grid) {
        s << "_grid_d" << grid_dims << "_z" << cell_size_bits << "_c" << cell_capacity << "_k" << max_span << "_e"
          << entry_capacity;
    }
    return s.str();
}

std::vector<std::string> RtlVariant::verilator_parameters() const {
    const bool is_float = format_bits == 0;
    auto parameter = [](const char* name, uint64_t value) { return std::string("-G") + name + "=" + std::to_string(value); };
    std::vector<std::string> parameters{parameter("M", m),
                                        parameter("AW", address_bits),
                                        parameter("FLOAT", is_float ? 1 : 0),
                                        parameter("WIDTH", is_float ? 32 : format_bits),
                                        parameter("COMPARE_LATENCY", compare_latency),
                                        parameter("FIFO_DEPTH", fifo_depth),
                                        parameter("BUFFER_DEPTH", buffer_depth)};
    if (grid) {
        for (const auto& [name, value] : {std::pair<const char*, uint64_t>{"LAT", tile_latency},
                                          {"DIMS", grid_dims},
                                          {"CELL_SIZE", cell_size_bits},
                                          {"CELL_CAPACITY", cell_capacity},
                                          {"MAX_SPAN", max_span},
                                          {"ENTRY_CAPACITY", entry_capacity}}) {
            parameters.push_back(parameter(name, value));
        }
    } else {
        parameters.push_back(parameter("TILE_BOXES", tile_boxes));
        parameters.push_back(parameter("TILE_LATENCY", tile_latency));
    }
    return parameters;
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
    if (config.grid_board()) {
        const GridConfig& g = config.grid;
        v.grid = true;
        v.tile_latency = config.tiles.load_latency_cycles;
        v.grid_dims = g.dims;
        std::memcpy(&v.cell_size_bits, &g.cell_size, sizeof v.cell_size_bits);
        v.cell_capacity = g.cell_capacity;
        v.max_span = g.max_span;
        v.entry_capacity = std::min<uint64_t>(g.entry_capacity, v.capacity() * g.max_span);
    }
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
    if (grid) {
        config.algorithm = BoardAlgorithm::kGrid;
        config.tiles.boxes = 0;
        config.grid.dims = grid_dims;
        std::memcpy(&config.grid.cell_size, &cell_size_bits, sizeof cell_size_bits);
        config.grid.cell_capacity = cell_capacity;
        config.grid.max_span = max_span;
        config.grid.entry_capacity = entry_capacity;
    }
    return config;
}

bool RtlVariant::serves(const BoardConfig& config, uint32_t boxes) const {
    const RtlVariant need = for_board(config, boxes);
    return m == need.m && format_bits == need.format_bits && compare_latency == need.compare_latency &&
           fifo_depth == need.fifo_depth && buffer_depth == need.buffer_depth && tile_boxes == need.tile_boxes &&
           (tile_boxes == 0 || tile_latency == need.tile_latency) && capacity() >= boxes && grid == need.grid &&
           (!grid || (tile_latency == need.tile_latency && grid_dims == need.grid_dims &&
                      cell_size_bits == need.cell_size_bits && cell_capacity == need.cell_capacity &&
                      max_span == need.max_span &&
                      entry_capacity == std::min(config.grid.entry_capacity, capacity() * max_span)));
}

// What the grid board's top cannot run (one line), or empty.
static std::string grid_rtl_unsupported(const BoardConfig& config) {
    if (config.tiles.cycles_per_box != 1) {
        return "the grid board RTL reads a box from six SSRAM banks in one slot (q = 1); cycles_per_box is " +
               std::to_string(config.tiles.cycles_per_box) + " (device.ssram_banks below 6)";
    }
    if (config.tiles.load_latency_cycles > kGridRtlMaxLatency) {
        return "the grid board RTL's SSRAM read latency is at most " + std::to_string(kGridRtlMaxLatency) +
               " slots; it is " + std::to_string(config.tiles.load_latency_cycles);
    }
    const uint64_t dims = config.grid.dims;
    if (dims * dims * dims > kGridRtlMaxCells) {
        return "the grid board RTL's count table holds at most " + std::to_string(kGridRtlMaxCells) +
               " cells (a register file); board.grid.dims " + std::to_string(dims) + " makes " +
               std::to_string(dims * dims * dims);
    }
    return {};
}

std::string rtl_unsupported(const BoardConfig& config) {
    if (config.grid_board()) {
        if (std::string why = grid_rtl_unsupported(config); !why.empty()) return why;
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
