#include "models/resources/whole_board_timing.h"

#include <stdexcept>

#include "models/resources/table_fields.h"

namespace cdvp {

namespace {

constexpr const char* kWholeBoardHeader =
    "family,board,format,m,latency,fifo,address_bits,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to";

// float32, or fixedK for K of 1 to 64 (the tops' WIDTH).
bool is_format(const std::string& text) {
    if (text == "float32") return true;
    const std::string fixed = "fixed";
    if (text.rfind(fixed, 0) != 0 || text.size() == fixed.size() || text.size() > fixed.size() + 2) return false;
    for (std::size_t k = fixed.size(); k < text.size(); ++k) {
        if (text[k] < '0' || text[k] > '9') return false;
    }
    const int width = std::stoi(text.substr(fixed.size()));
    return width >= 1 && width <= 64;
}

const char* board_name(bool grid) { return grid ? "grid" : "all_pairs"; }

}  // namespace

WholeBoardTable WholeBoardTable::parse(const std::string& csv, const std::string& origin) {
    WholeBoardTable table;
    read_table(csv, origin, kWholeBoardHeader, [&](const std::vector<std::string>& f, const std::string& where) {
        Row row;
        const TableRowKey key = table_row_key(f, where);
        row.family = key.family;
        row.board = key.piece;
        row.format = key.format;
        row.m = key.m;
        if (row.board != "all_pairs" && row.board != "grid") {
            throw std::invalid_argument(where + ": board: expected all_pairs or grid, got '" + row.board + "'");
        }
        if (!is_format(row.format)) {
            throw std::invalid_argument(where + ": format: expected float32 or fixed1 to fixed64, got '" + row.format +
                                        "'");
        }
        if (row.m == 0) throw std::invalid_argument(where + ": m: expected 1 or more, got '" + f[3] + "'");
        row.compare_latency = static_cast<uint32_t>(table_count(f[4], where, "latency"));
        if (f[5] != "block_ram" && f[5] != "distributed") {
            throw std::invalid_argument(where + ": fifo: expected block_ram or distributed, got '" + f[5] + "'");
        }
        row.fifo_memory = f[5] == "block_ram" ? FifoMemory::kBlockRam : FifoMemory::kDistributed;
        row.address_bits = static_cast<uint32_t>(table_count(f[6], where, "address_bits"));
        if (row.address_bits == 0 || row.address_bits > 32) {
            throw std::invalid_argument(where + ": address_bits: expected 1 to 32, got '" + f[6] + "'");
        }
        row.speed_grade = speed_grade_field(f[7], where);
        row.path = path_delay_of(f, 8, where);
        table.rows_.push_back(row);
    });
    return table;
}

WholeBoardPath WholeBoardTable::path(const TimedBoard& board) const {
    const std::string which = std::string("the ") + (board.grid ? "grid" : "all-pairs") + " board";
    if (board.tiled) return {std::nullopt, "no whole-board timing of " + which + " with its boxes in SSRAM tiles"};
    const auto serves = [&](const Row& row) {
        return row.board == board_name(board.grid) && row.family == board.family &&
               row.speed_grade == board.speed_grade && row.format == board.format &&
               row.compare_latency == board.compare_latency && row.fifo_memory == board.fifo_memory &&
               row.address_bits >= board.address_bits;
    };
    // The narrowest stored width that holds the board's boxes, then the
    // stored m on either side of the board's at that width.
    uint32_t bits = 0;
    for (const Row& row : rows_) {
        if (serves(row) && (bits == 0 || row.address_bits < bits)) bits = row.address_bits;
    }
    const Row* below = nullptr;
    const Row* above = nullptr;
    for (const Row& row : rows_) {
        if (!serves(row) || row.address_bits != bits) continue;
        if (row.m <= board.m && (below == nullptr || row.m > below->m)) below = &row;
        if (row.m >= board.m && (above == nullptr || row.m < above->m)) above = &row;
    }
    if (below == nullptr || above == nullptr) {
        return {std::nullopt, "no whole-board timing of " + which + " (" + board.family + " -" +
                                  std::to_string(board.speed_grade) + ", " + board.format + ", compare latency " +
                                  std::to_string(board.compare_latency) + ", pair FIFO in " +
                                  (board.fifo_memory == FifoMemory::kBlockRam ? "block RAM" : "LUTs") + ", " +
                                  std::to_string(board.address_bits) + " address bits) stored around m = " +
                                  std::to_string(board.m)};
    }
    return {below->path.ns >= above->path.ns ? below->path : above->path, ""};
}

}  // namespace cdvp
