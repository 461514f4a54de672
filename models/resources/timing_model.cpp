#include "models/resources/timing_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "models/resources/table_fields.h"

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

TimingTable TimingTable::parse(const std::string& csv, const std::string& origin) {
    TimingTable table;
    read_table(csv, origin, kTimingTableHeader, [&](const std::vector<std::string>& f, const std::string& where) {
        Row row;
        static_cast<TableRowKey&>(row) = table_row_key(f, where);
        row.latency = static_cast<uint32_t>(table_count(f[4], where, "latency"));
        row.speed_grade = static_cast<uint32_t>(table_count(f[5], where, "speed_grade"));
        if (row.speed_grade == 0) {
            throw std::invalid_argument(where + ": speed_grade: expected a grade, got '" + f[5] + "'");
        }
        row.path.ns = path_ns(f[6], where);
        row.path.luts = static_cast<uint32_t>(table_count(f[7], where, "luts"));
        row.path.carry_cells = static_cast<uint32_t>(table_count(f[8], where, "carry_cells"));
        row.path.wide_muxes = static_cast<uint32_t>(table_count(f[9], where, "wide_muxes"));
        row.path.from = endpoint(f[10], where, "from");
        row.path.to = endpoint(f[11], where, "to");
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

const PieceTiming& slowest_of(const std::vector<PieceTiming>& pieces, bool held_only) {
    const PieceTiming* slowest = nullptr;
    for (const PieceTiming& piece : pieces) {
        if ((piece.holds_clock || !held_only) && (slowest == nullptr || piece.path.ns > slowest->path.ns)) {
            slowest = &piece;
        }
    }
    if (slowest == nullptr) throw std::logic_error("a board's timing without a piece its clock is held to");
    return *slowest;
}

}  // namespace

const PieceTiming& BoardTiming::limiting() const { return slowest_of(pieces, true); }

const PieceTiming& BoardTiming::slowest() const { return slowest_of(pieces, false); }

BoardTiming board_timing(const TimingTable& table, const TimedBoard& board) {
    const std::string& family = board.family;
    const uint32_t grade = board.speed_grade;
    const std::string lane = board.format + " comparison lane at compare latency " +
                             std::to_string(board.compare_latency);
    const std::string fifo = board.fifo_memory == FifoMemory::kBlockRam ? "pair FIFO in block RAM" : "pair FIFO in LUTs";
    BoardTiming timing;
    timing.speed_grade = grade;
    timing.pieces.push_back({"lane", lane, table.lane(family, grade, board.format, board.compare_latency)});
    if (board.grid) {
        // Written to the model's slots, not to a clock (docs/grid_board.md),
        // so reported, not held to: the cell-function unit's binary32 adder is
        // one of its four stages (GridConfig::kCellFunctionSlots), the
        // sequencer's setup divider and bounds adders one step a slot, and the
        // one-cell filter sits between the lanes' hit registers and the pair
        // FIFO with no register of its own (it lengthens the FIFO's path).
        timing.pieces.push_back({"cell_function", board.format + " cell-function unit",
                                 table.cell_function(family, grade, board.format), false});
        timing.pieces.push_back({"cell_loader", board.format + " cell loader",
                                 table.cell_loader(family, grade, board.format)});
        timing.pieces.push_back({"sequencer", "binning sequencer", table.grid_sequencer(family, grade), false});
        timing.pieces.push_back({"one_cell_filter", "one-cell filter in front of the pair FIFO",
                                 table.home_cell_filter(family, grade, board.m), false});
    } else if (board.tiled) {
        timing.pieces.push_back({"tile_walker", "tile walker", table.tile_walker(family, grade, board.m)});
    } else {
        const PathDelay generator = table.address_generator(family, grade, board.m);
        timing.pieces.push_back({"address_generator", "address generator", generator});
    }
    // Lanes of compare latency 2 or more give the FIFO their hits' count a
    // cycle ahead; the grid board's pass through the one-cell filter first.
    const bool counted_ahead = !board.grid && board.compare_latency >= 2;
    const PathDelay collector =
        table.pair_collector(family, grade, board.m, fifo_memory_name(board.fifo_memory), counted_ahead);
    // The seed's board holds its clock to the FIFO; the grid board's FIFO is
    // reported with the one-cell filter that lengthens its path.
    timing.pieces.push_back({"pair_fifo", fifo, collector, !board.grid});
    timing.pieces.push_back({"controller", "controller", table.control(family, grade)});
    return timing;
}

}  // namespace cdvp
