// How fast a board configuration can be clocked, from synthesis: each piece
// that decides it (comparison lane per number format and compare latency,
// address generator or tile walker and pair FIFO per m, controller; on the
// grid board the cell-function unit and cell loader per format, the one-cell
// filter per m and the binning sequencer in place of the address generator) was
// synthesised with Yosys and its longest register-to-register path found by
// Yosys's static timing analysis with the family's cell delays at each speed
// grade (scripts/timing.sh; rows in timing.csv, compiled into cdvp). A board
// runs no faster than its slowest piece, nor than the whole board timed as one
// design (whole_board_timing.h).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "models/resources/resource_model.h"
#include "models/resources/table_fields.h"

namespace cdvp {

class WholeBoardTable;

// One piece's longest register-to-register path.
struct PathDelay {
    double ns = 0;
    // What it runs through: LUT levels, carry cells and wide multiplexers
    // (MUXF5 to MUXF9), from and to a flip_flop, block_ram or lut_ram.
    uint32_t luts = 0;
    uint32_t carry_cells = 0;
    uint32_t wide_muxes = 0;
    std::string from, to;
    double fmax_mhz() const { return 1e3 / ns; }
};

// A table row's path columns (path_ns, luts, carry_cells, wide_muxes, from,
// to) from fields[first] on, and its speed grade column (a grade, not '-').
// 'where' ("ORIGIN:LINE") names the row in errors. Throw std::invalid_argument.
PathDelay path_delay_of(const std::vector<std::string>& fields, std::size_t first, const std::string& where);
uint32_t speed_grade_field(const std::string& text, const std::string& where);

// The timing table: rows keyed by family, piece, format, compare latency and
// speed grade, at each m for the pieces that grow with it.
class TimingTable {
public:
    // Parses the CSV that scripts/timing.sh prints; 'origin' names it in
    // errors. Throws std::invalid_argument "ORIGIN:LINE: ..." on a bad row.
    static TimingTable parse(const std::string& csv, const std::string& origin);
    // The table compiled into cdvp (models/resources/timing.csv).
    static const TimingTable& stored();

    // Throw std::invalid_argument naming what is missing.
    // A latency past the deepest synthesised one takes that row: the lane's
    // further stages only delay its AND (compare_lane.v).
    PathDelay lane(const std::string& family, uint32_t speed_grade, const std::string& format,
                   uint32_t latency) const;
    // At an m between two synthesised points: the slower of the two.
    PathDelay address_generator(const std::string& family, uint32_t speed_grade, uint32_t m) const;
    PathDelay tile_walker(const std::string& family, uint32_t speed_grade, uint32_t m) const;
    // memory: where the FIFO's entries live, "block_ram" or "distributed".
    // counted_ahead: fed by lanes of compare latency 2 or more, it counts
    // their hits a cycle ahead (pair_collector.v's COUNT_AHEAD: the rows of
    // latency 2); else in the cycle they arrive (latency '-').
    PathDelay pair_collector(const std::string& family, uint32_t speed_grade, uint32_t m, const std::string& memory,
                             bool counted_ahead) const;
    PathDelay control(const std::string& family, uint32_t speed_grade) const;
    // The grid board's pieces. A fixedK format between two synthesised widths
    // takes the slower of the two neighbours.
    PathDelay cell_function(const std::string& family, uint32_t speed_grade, const std::string& format) const;
    PathDelay cell_loader(const std::string& family, uint32_t speed_grade, const std::string& format) const;
    PathDelay home_cell_filter(const std::string& family, uint32_t speed_grade, uint32_t m) const;
    // Synthesised at float32, m = 8, as its resource row: its long paths
    // (setup divider, bounds adders) do not grow with m.
    PathDelay grid_sequencer(const std::string& family, uint32_t speed_grade) const;
    // The family's speed grades, ascending (the slowest first: -4 on Virtex-II, -1 on UltraScale+).
    std::vector<uint32_t> speed_grades(const std::string& family) const;

private:
    struct Row : TableRowKey {
        uint32_t latency = 0;  // compare lanes; the pair FIFO's 2: its hits counted a cycle ahead
        uint32_t speed_grade = 0;
        PathDelay path;
    };
    using Key = std::tuple<std::string, std::string, std::string, uint32_t>;  // family, piece, format, grade
    const std::vector<std::size_t>& rows_of(std::string_view family, std::string_view piece, std::string_view format,
                                            uint32_t speed_grade, const std::string& what) const;
    // Of the rows of that latency ('-': 0).
    PathDelay by_m(std::string_view family, std::string_view piece, std::string_view format, uint32_t speed_grade,
                   uint32_t m, const std::string& what, uint32_t latency = 0) const;
    PathDelay by_format(const std::string& family, const std::string& piece, uint32_t speed_grade,
                        const std::string& format, const std::string& what) const;
    std::vector<Row> rows_;
    std::map<Key, std::vector<std::size_t>, std::less<>> by_key_;
    std::map<std::string, std::vector<uint32_t>, std::less<>> grades_;  // ascending, by family
};

// A piece of a board (or the whole board as one design) with its longest path.
struct PieceTiming {
    // lane, address_generator or tile_walker, pair_fifo, controller; on the
    // grid board cell_function, cell_loader, one_cell_filter, sequencer; and
    // whole_board, the board synthesised as one design
    std::string key;
    std::string piece;  // "float32 comparison lane at compare latency 2", "pair FIFO in block RAM", ...
    PathDelay path;
};

// TEMPORARY, while the grid board's cell-function unit, one-cell filter and
// binning sequencer are pipelined for the clock (they are written to the
// model's slots, not to a clock: docs/grid_board.md, "Timing"): their paths
// are reported but the clock is not held to them, nor to the grid board's
// whole-board path, which runs through them, nor to its pair FIFO, which the
// unregistered one-cell filter makes count its hits in their cycle (on the
// VU9P it would refuse the presets' 250 and 300 MHz: 246.7 MHz at -1, 296.6
// at -2, m = 8). Set it to false once they are pipelined;
// BoardTiming::awaiting_pipelining is then always empty and goes with this
// constant.
constexpr bool kGridPiecesAwaitPipelining = true;

struct BoardTiming {
    uint32_t speed_grade = 0;
    // Every piece the clock is held to, the whole board among them when its
    // row is stored.
    std::vector<PieceTiming> pieces;
    // Reported, not held to (kGridPiecesAwaitPipelining).
    std::vector<PieceTiming> awaiting_pipelining;
    // Why the whole board is not among the pieces (no row stored for it):
    // the Fmax is then the pieces' alone. Empty when it is.
    std::string whole_board_missing;
    // The slowest piece the clock is held to: it sets the board's Fmax.
    const PieceTiming& limiting() const;
    double fmax_mhz() const { return limiting().path.fmax_mhz(); }
    // The slowest of all, those awaiting pipelining included.
    const PieceTiming& slowest() const;
};

// What of a board configuration the timing depends on.
struct TimedBoard {
    std::string family;
    uint32_t speed_grade = 0;
    std::string format;        // float32 or fixedK
    uint32_t m = 1;
    uint32_t compare_latency = 0;
    FifoMemory fifo_memory = FifoMemory::kBlockRam;  // BoardResources::pair_fifo_memory
    bool tiled = false;        // boxes in SSRAM tiles: the tile walker, not the address generator
    bool grid = false;         // the grid board: its sequencer, loader and cell-function units instead
    uint32_t address_bits = 9; // the box indices' width: the board holds 2^address_bits boxes at most
};
// The board's pieces from the piece table and the whole board from the
// whole-board table (whole_board_timing.h), when it has the board's row.
BoardTiming board_timing(const TimingTable& table, const WholeBoardTable& whole, const TimedBoard& board);

}  // namespace cdvp
