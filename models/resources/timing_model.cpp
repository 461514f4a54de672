#include "models/resources/timing_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "models/resources/table_fields.h"
#include "models/resources/whole_board_timing.h"

namespace cdvp {

namespace {

constexpr const char* kTimingTableHeader =
    "family,piece,format,m,latency,speed_grade,path_ns,luts,carry_cells,wide_muxes,from,to";

// A path delay in ns: finite and positive.
double path_ns(const std::string& text, const std::string& where) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value) || value <= 0) {
        throw std::invalid_argument(where + ": path_ns: expected a positive number of ns, got '" + text + "'");
    }
    return value;
}

std::string endpoint(const std::string& text, const std::string& where, const char* column) {
    if (text != "flip_flop" && text != "block_ram" && text != "lut_ram") {
        throw std::invalid_argument(where + ": " + column + ": expected flip_flop, block_ram or lut_ram, got '" + text +
                                    "'");
    }
    return text;
}

std::string grade_text(uint32_t speed_grade) { return "speed grade -" + std::to_string(speed_grade); }

}  // namespace

PathDelay path_delay_of(const std::vector<std::string>& fields, std::size_t first, const std::string& where) {
    PathDelay path;
    path.ns = path_ns(fields.at(first), where);
    path.luts = static_cast<uint32_t>(table_count(fields.at(first + 1), where, "luts"));
    path.carry_cells = static_cast<uint32_t>(table_count(fields.at(first + 2), where, "carry_cells"));
    path.wide_muxes = static_cast<uint32_t>(table_count(fields.at(first + 3), where, "wide_muxes"));
    path.from = endpoint(fields.at(first + 4), where, "from");
    path.to = endpoint(fields.at(first + 5), where, "to");
    return path;
}

uint32_t speed_grade_field(const std::string& text, const std::string& where) {
    const auto grade = static_cast<uint32_t>(table_count(text, where, "speed_grade"));
    if (grade == 0) throw std::invalid_argument(where + ": speed_grade: expected a grade, got '" + text + "'");
    return grade;
}

TimingTable TimingTable::parse(const std::string& csv, const std::string& origin) {
    TimingTable table;
    read_table(csv, origin, kTimingTableHeader, [&](const std::vector<std::string>& f, const std::string& where) {
        Row row;
        static_cast<TableRowKey&>(row) = table_row_key(f, where);
        row.latency = static_cast<uint32_t>(table_count(f[4], where, "latency"));
        row.speed_grade = speed_grade_field(f[5], where);
        row.path = path_delay_of(f, 6, where);
        table.rows_.push_back(row);
    });
    for (std::size_t k = 0; k < table.rows_.size(); ++k) {
        const Row& row = table.rows_[k];
        table.by_key_[{row.family, row.piece, row.format, row.speed_grade}].push_back(k);
        std::vector<uint32_t>& grades = table.grades_[row.family];
        if (std::find(grades.begin(), grades.end(), row.speed_grade) == grades.end()) {
            grades.insert(std::upper_bound(grades.begin(), grades.end(), row.speed_grade), row.speed_grade);
        }
    }
    return table;
}

const std::vector<std::size_t>& TimingTable::rows_of(std::string_view family, std::string_view piece,
                                                     std::string_view format, uint32_t speed_grade,
                                                     const std::string& what) const {
    const auto rows = by_key_.find(std::make_tuple(family, piece, format, speed_grade));
    if (rows == by_key_.end()) {
        throw std::invalid_argument("no timing of the " + what + " for the " + std::string(family) + " family at " +
                                    grade_text(speed_grade));
    }
    return rows->second;
}

PathDelay TimingTable::lane(const std::string& family, uint32_t speed_grade, const std::string& format,
                            uint32_t latency) const {
    const std::string what = format + " comparison lane";
    const Row* deepest = nullptr;
    for (const std::size_t k : rows_of(family, "compare_lane", format, speed_grade, what)) {
        const Row& row = rows_[k];
        if (row.latency == latency) return row.path;
        if (row.latency < latency && (deepest == nullptr || row.latency > deepest->latency)) deepest = &row;
    }
    if (deepest == nullptr) {
        throw std::invalid_argument("no timing of the " + what + " at compare latency " + std::to_string(latency) +
                                    " for the " + family + " family");
    }
    return deepest->path;
}

PathDelay TimingTable::by_m(std::string_view family, std::string_view piece, std::string_view format,
                            uint32_t speed_grade, uint32_t m, const std::string& what, uint32_t latency) const {
    const Row* below = nullptr;
    const Row* above = nullptr;
    for (const std::size_t k : rows_of(family, piece, format, speed_grade, what)) {
        const Row& row = rows_[k];
        if (row.latency != latency) continue;
        if (row.m <= m && (below == nullptr || row.m > below->m)) below = &row;
        if (row.m >= m && (above == nullptr || row.m < above->m)) above = &row;
    }
    if (below == nullptr || above == nullptr) {
        throw std::invalid_argument("no timing of the " + what + " around m = " + std::to_string(m) + " for the " +
                                    std::string(family) + " family");
    }
    return below->path.ns >= above->path.ns ? below->path : above->path;
}

PathDelay TimingTable::address_generator(const std::string& family, uint32_t speed_grade, uint32_t m) const {
    return by_m(family, "address_generator", "-", speed_grade, m, "address generator");
}

PathDelay TimingTable::tile_walker(const std::string& family, uint32_t speed_grade, uint32_t m) const {
    return by_m(family, "tile_walker", "-", speed_grade, m, "tile walker");
}

PathDelay TimingTable::pair_collector(const std::string& family, uint32_t speed_grade, uint32_t m,
                                      const std::string& memory, bool counted_ahead) const {
    const std::string what = "pair FIFO (" + memory + (counted_ahead ? ", hits counted a cycle ahead)" : ")");
    return by_m(family, "pair_collector", memory, speed_grade, m, what, counted_ahead ? 2 : 0);
}

PathDelay TimingTable::control(const std::string& family, uint32_t speed_grade) const {
    const std::vector<std::size_t>& rows = rows_of(family, "board_control", "-", speed_grade, "controller");
    return rows_[rows.front()].path;
}

PathDelay TimingTable::by_format(const std::string& family, const std::string& piece, uint32_t speed_grade,
                                 const std::string& format, const std::string& what) const {
    const std::string fixed = "fixed";
    if (format.rfind(fixed, 0) != 0) return rows_[rows_of(family, piece, format, speed_grade, what).front()].path;
    const uint32_t width = static_cast<uint32_t>(std::strtoul(format.c_str() + fixed.size(), nullptr, 10));
    const Row* below = nullptr;
    const Row* above = nullptr;
    for (uint32_t k = 1; k <= 64; ++k) {
        const auto rows = by_key_.find(std::make_tuple(family, piece, fixed + std::to_string(k), speed_grade));
        if (rows == by_key_.end()) continue;
        const Row& row = rows_[rows->second.front()];
        if (k <= width) below = &row;
        if (k >= width && above == nullptr) above = &row;
    }
    if (below == nullptr || above == nullptr) {
        throw std::invalid_argument("no timing of the " + what + " for the " + family + " family at " +
                                    grade_text(speed_grade) + " (no synthesised width on both sides)");
    }
    return below->path.ns >= above->path.ns ? below->path : above->path;
}

PathDelay TimingTable::cell_function(const std::string& family, uint32_t speed_grade, const std::string& format) const {
    return by_format(family, "grid_cell_function", speed_grade, format, format + " cell-function unit");
}

PathDelay TimingTable::cell_loader(const std::string& family, uint32_t speed_grade, const std::string& format) const {
    return by_format(family, "cell_loader", speed_grade, format, format + " cell loader");
}

PathDelay TimingTable::home_cell_filter(const std::string& family, uint32_t speed_grade, uint32_t m) const {
    return by_m(family, "home_cell_filter", "-", speed_grade, m, "one-cell filter");
}

PathDelay TimingTable::grid_sequencer(const std::string& family, uint32_t speed_grade) const {
    return by_m(family, "grid_sequencer", "float32", speed_grade, 8, "binning sequencer");
}

std::vector<uint32_t> TimingTable::speed_grades(const std::string& family) const {
    const auto grades = grades_.find(family);
    return grades == grades_.end() ? std::vector<uint32_t>() : grades->second;
}

namespace {

const PieceTiming* slowest_of(const std::vector<PieceTiming>& pieces, const PieceTiming* slowest = nullptr) {
    for (const PieceTiming& piece : pieces) {
        if (slowest == nullptr || piece.path.ns > slowest->path.ns) slowest = &piece;
    }
    return slowest;
}

// The whole board's piece: its path's ends and depth name it.
std::string whole_board_piece(const PathDelay& path) {
    const auto count = [](uint32_t n, const char* what) { return std::to_string(n) + " " + what; };
    const auto end = [](const std::string& kind) {
        return kind == "block_ram" ? "block RAM" : kind == "lut_ram" ? "LUT RAM" : "flip-flop";
    };
    return "whole board as one design (longest path: " + std::string(end(path.from)) + " to " + end(path.to) +
           " through " + count(path.luts, "LUTs") + ", " + count(path.carry_cells, "carry cells") + " and " +
           count(path.wide_muxes, "wide multiplexers") + ")";
}

}  // namespace

const PieceTiming& BoardTiming::limiting() const {
    const PieceTiming* slowest = slowest_of(pieces);
    if (slowest == nullptr) throw std::logic_error("a board's timing without a piece its clock is held to");
    return *slowest;
}

const PieceTiming& BoardTiming::slowest() const { return *slowest_of(awaiting_pipelining, &limiting()); }

BoardTiming board_timing(const TimingTable& table, const WholeBoardTable& whole, const TimedBoard& board) {
    const std::string& family = board.family;
    const uint32_t grade = board.speed_grade;
    const std::string lane = board.format + " comparison lane at compare latency " +
                             std::to_string(board.compare_latency);
    const std::string fifo = board.fifo_memory == FifoMemory::kBlockRam ? "pair FIFO in block RAM" : "pair FIFO in LUTs";
    BoardTiming timing;
    timing.speed_grade = grade;
    // The grid board's pieces written to the model's slots, not to a clock,
    // and so the grid board's whole path, while they are being pipelined.
    std::vector<PieceTiming>& grid_pieces = kGridPiecesAwaitPipelining ? timing.awaiting_pipelining : timing.pieces;
    timing.pieces.push_back({"lane", lane, table.lane(family, grade, board.format, board.compare_latency)});
    if (board.grid) {
        // The cell-function unit's binary32 adder is one of its four stages
        // (GridConfig::kCellFunctionSlots), the sequencer's setup divider and
        // bounds adders one step a slot, and the one-cell filter sits between
        // the lanes' hit registers and the pair FIFO with no register of its own.
        grid_pieces.push_back({"cell_function", board.format + " cell-function unit",
                               table.cell_function(family, grade, board.format)});
        timing.pieces.push_back({"cell_loader", board.format + " cell loader",
                                 table.cell_loader(family, grade, board.format)});
        grid_pieces.push_back({"sequencer", "binning sequencer", table.grid_sequencer(family, grade)});
        grid_pieces.push_back({"one_cell_filter", "one-cell filter in front of the pair FIFO",
                               table.home_cell_filter(family, grade, board.m)});
    } else if (board.tiled) {
        timing.pieces.push_back({"tile_walker", "tile walker", table.tile_walker(family, grade, board.m)});
    } else {
        const PathDelay generator = table.address_generator(family, grade, board.m);
        timing.pieces.push_back({"address_generator", "address generator", generator});
    }
    // Lanes of compare latency 2 or more give the FIFO their hits' count a
    // cycle ahead; the grid board's pass through the one-cell filter first,
    // which has no register of its own (kGridPiecesAwaitPipelining).
    const bool counted_ahead = !board.grid && board.compare_latency >= 2;
    (board.grid ? grid_pieces : timing.pieces)
        .push_back({"pair_fifo", fifo,
                    table.pair_collector(family, grade, board.m, fifo_memory_name(board.fifo_memory),
                                         counted_ahead)});
    timing.pieces.push_back({"controller", "controller", table.control(family, grade)});
    const WholeBoardPath whole_path = whole.path(board);
    if (whole_path.path) {
        (board.grid ? grid_pieces : timing.pieces)
            .push_back({"whole_board", whole_board_piece(*whole_path.path), *whole_path.path});
    } else {
        timing.whole_board_missing = whole_path.missing;
    }
    return timing;
}

}  // namespace cdvp
