// How fast a board configuration can be clocked, from synthesis: each piece
// that decides it (comparison lane per number format and compare latency,
// address generator or tile walker and pair FIFO per m, controller; on the
// grid board the cell-function unit and cell loader per format, the one-cell
// filter per m and the binning sequencer in place of the address generator) was
// synthesised with Yosys and its longest register-to-register path found by
// Yosys's static timing analysis with the family's cell delays at each speed
// grade (scripts/timing.sh; rows in timing.csv, compiled into cdvp). A board
// runs no faster than its slowest piece (of those its clock is held to).
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

// A board's pieces with their paths, as the timing table gives them.
struct PieceTiming {
    // lane, address_generator or tile_walker, pair_fifo, controller; on the
    // grid board cell_function, cell_loader, one_cell_filter, sequencer
    std::string key;
    std::string piece;  // "float32 comparison lane at compare latency 2", "pair FIFO in block RAM", ...
    PathDelay path;
    // Whether the board's clock is held to this piece. The grid board's
    // cell-function unit (its adder one of the model's four stages), one-cell
    // filter (combinational in front of the pair FIFO, so the FIFO with it)
    // and binning sequencer (its setup divider and bounds adders one step a
    // slot) are written to the model's slots, not to a clock: their paths are
    // reported, not held to (docs/grid_board.md).
    bool holds_clock = true;
};
struct BoardTiming {
    uint32_t speed_grade = 0;
    std::vector<PieceTiming> pieces;
    // The slowest piece the clock is held to: it sets the board's Fmax.
    const PieceTiming& limiting() const;
    double fmax_mhz() const { return limiting().path.fmax_mhz(); }
    // The slowest piece of all, as the RTL is written.
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
};
BoardTiming board_timing(const TimingTable& table, const TimedBoard& board);

}  // namespace cdvp
