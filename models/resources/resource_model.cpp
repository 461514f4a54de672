#include "models/resources/resource_model.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "models/resources/table_fields.h"

namespace cdvp {

Resources& Resources::operator+=(const Resources& other) {
    luts += other.luts;
    flip_flops += other.flip_flops;
    carry_cells += other.carry_cells;
    block_rams += other.block_rams;
    multipliers += other.multipliers;
    return *this;
}

Resources operator*(double times, const Resources& r) {
    return {times * r.luts, times * r.flip_flops, times * r.carry_cells, times * r.block_rams,
            times * r.multipliers};
}

namespace {

constexpr const char* kSynthesisTableHeader =
    "family,piece,format,m,address_bits,fifo_depth,luts,lutram_luts,flip_flops,carry_cells,block_rams_18k,"
    "multipliers";
Resources lerp(const Resources& a, const Resources& b, double t) { return (1 - t) * a + t * b; }

}  // namespace

SynthesisTable SynthesisTable::parse(const std::string& csv, const std::string& origin) {
    SynthesisTable table;
    read_table(csv, origin, kSynthesisTableHeader, [&](const std::vector<std::string>& f, const std::string& where) {
        Row row;
        static_cast<TableRowKey&>(row) = table_row_key(f, where);
        row.resources.luts = table_count(f[6], where, "luts") + table_count(f[7], where, "lutram_luts");
        row.resources.flip_flops = table_count(f[8], where, "flip_flops");
        row.resources.carry_cells = table_count(f[9], where, "carry_cells");
        row.resources.block_rams = table_count(f[10], where, "block_rams_18k");
        row.resources.multipliers = table_count(f[11], where, "multipliers");
        table.rows_.push_back(row);
    });
    for (std::size_t k = 0; k < table.rows_.size(); ++k) {
        const Row& row = table.rows_[k];
        table.by_key_[{row.family, row.piece, row.format}].push_back(k);
    }
    for (auto& [name, rows] : table.by_key_) {
        std::stable_sort(rows.begin(), rows.end(),
                         [&](std::size_t a, std::size_t b) { return table.rows_[a].m < table.rows_[b].m; });
    }
    return table;
}

const std::vector<std::size_t>* SynthesisTable::rows_of(std::string_view family, std::string_view piece,
                                                         std::string_view format) const {
    const auto rows = by_key_.find(std::make_tuple(family, piece, format));
    return rows == by_key_.end() ? nullptr : &rows->second;
}

const SynthesisTable::Row* SynthesisTable::find(std::string_view family, std::string_view piece,
                                                std::string_view format) const {
    const std::vector<std::size_t>* rows = rows_of(family, piece, format);
    if (rows == nullptr) return nullptr;
    // The first in the file, as a scan would find it.
    return &rows_[*std::min_element(rows->begin(), rows->end())];
}

Resources SynthesisTable::lane(const std::string& family, const std::string& format) const {
    const Row* row = find(family, "compare_lane", format);
    if (row == nullptr) {
        throw std::invalid_argument("no synthesis of a " + format + " comparison lane for the " + family + " family");
    }
    return row->resources;
}

Resources SynthesisTable::control(const std::string& family) const {
    const Row* row = find(family, "board_control", "-");
    if (row == nullptr) throw std::invalid_argument("no synthesis of the controller for the " + family + " family");
    return row->resources;
}

Resources SynthesisTable::cell_function(const std::string& family, const std::string& format) const {
    if (const Row* row = find(family, "grid_cell_function", format)) return row->resources;
    // fixedK between two synthesised widths: interpolated in K (the unit is
    // the float adder and multiplier either way; K sizes only its converter).
    const auto width = [](std::string_view name) {
        return name.rfind("fixed", 0) == 0 ? std::atoi(std::string(name.substr(5)).c_str()) : 0;
    };
    const int k = width(format);
    const Row* below = nullptr;
    const Row* above = nullptr;
    for (const Row& row : rows_) {
        const int w = row.family == family && row.piece == "grid_cell_function" ? width(row.format) : 0;
        if (w == 0 || k == 0) continue;
        if (w <= k && (below == nullptr || w > width(below->format))) below = &row;
        if (w >= k && (above == nullptr || w < width(above->format))) above = &row;
    }
    if (below == nullptr || above == nullptr) {
        throw std::invalid_argument("no synthesis of a " + format + " cell-function unit for the " + family + " family");
    }
    const int lo = width(below->format), hi = width(above->format);
    return lo == hi ? below->resources : lerp(below->resources, above->resources, double(k - lo) / double(hi - lo));
}

Resources SynthesisTable::home_cell_filter(const std::string& family, uint32_t m) const {
    return by_m(family, "home_cell_filter", "-", m);
}

Resources SynthesisTable::grid_sequencer(const std::string& family) const {
    const Row* row = find(family, "grid_sequencer", "float32");
    if (row == nullptr) throw std::invalid_argument("no synthesis of the grid sequencer for the " + family + " family");
    return row->resources;
}

Resources SynthesisTable::by_m(std::string_view family, std::string_view piece, std::string_view format,
                               uint32_t m) const {
    const Row* below = nullptr;
    const Row* above = nullptr;
    if (const std::vector<std::size_t>* rows = rows_of(family, piece, format)) {
        for (const std::size_t k : *rows) {
            const Row& row = rows_[k];
            if (row.m <= m && (below == nullptr || row.m > below->m)) below = &row;
            if (row.m >= m && (above == nullptr || row.m < above->m)) above = &row;
        }
    }
    if (below == nullptr || above == nullptr) {
        const std::string in_format = format == "-" ? "" : " (" + std::string(format) + ")";
        throw std::invalid_argument("no synthesis of the " + std::string(piece) + in_format + " around m = " +
                                    std::to_string(m) + " for the " + std::string(family) + " family");
    }
    if (below == above) return below->resources;
    return lerp(below->resources, above->resources, double(m - below->m) / double(above->m - below->m));
}

Resources SynthesisTable::address_generator(const std::string& family, uint32_t m) const {
    return by_m(family, "address_generator", "-", m);
}

Resources SynthesisTable::pair_collector(const std::string& family, uint32_t m, const std::string& memory) const {
    return by_m(family, "pair_collector", memory, m);
}

std::vector<std::string> SynthesisTable::families() const {
    std::vector<std::string> names;
    for (const Row& row : rows_) {
        if (std::find(names.begin(), names.end(), row.family) == names.end()) names.push_back(row.family);
    }
    return names;
}

std::vector<std::string> SynthesisTable::formats(const std::string& family) const {
    std::vector<std::string> names;
    for (const Row& row : rows_) {
        if (row.family == family && row.piece == "compare_lane") names.push_back(row.format);
    }
    return names;
}

const char* fifo_memory_name(FifoMemory memory) {
    return memory == FifoMemory::kBlockRam ? "block_ram" : "distributed";
}

BoardResources board_resources(const SynthesisTable& table, const DeviceCapacity& device, const std::string& format,
                               uint32_t m, double memory_block_rams) {
    const std::string& family = device.family;
    BoardResources r;
    r.lanes = double(2 * m - 1) * table.lane(family, format);
    r.coordinate_memories.block_rams = memory_block_rams;
    r.address_generator = table.address_generator(family, m);
    r.pair_collector = table.pair_collector(family, m, fifo_memory_name(FifoMemory::kBlockRam));
    r.pair_fifo_memory = FifoMemory::kBlockRam;
    if (memory_block_rams + r.pair_collector.block_rams > device.block_rams) {
        r.pair_collector = table.pair_collector(family, m, fifo_memory_name(FifoMemory::kDistributed));
        r.pair_fifo_memory = FifoMemory::kDistributed;
    }
    r.control = table.control(family);
    return r;
}

BoardResources grid_board_resources(const SynthesisTable& table, const DeviceCapacity& device,
                                    const std::string& format, uint32_t m, double cell_buffer_block_rams) {
    BoardResources r = board_resources(table, device, format, m, cell_buffer_block_rams);
    r.grid_blocks = double(kCellFunctionUnits) * table.cell_function(device.family, format) +
                    table.home_cell_filter(device.family, m) + table.grid_sequencer(device.family);
    r.memories_hold = "the cell buffer";
    return r;
}

Utilisation utilisation(const Resources& used, const DeviceCapacity& device) {
    Utilisation u;
    u.luts = used.luts / device.luts;
    u.flip_flops = used.flip_flops / device.flip_flops;
    u.block_rams = used.block_rams / device.block_rams;
    if (u.luts > 1) {
        u.overflow = "LUTs";
    } else if (u.flip_flops > 1) {
        u.overflow = "flip-flops";
    } else if (u.block_rams > 1) {
        u.overflow = "block RAMs";
    }
    return u;
}

}  // namespace cdvp
