// The whole board timed as one design: each top (collision_board_top.v for
// the all-pairs board, grid_board_top.v for the grid board) synthesised with
// Yosys, its host bus and SSRAM ports behind registers, and its longest
// register-to-register path found by Yosys's static timing analysis at each
// speed grade (scripts/timing.sh --board-row; rows in whole_board_timing.csv,
// compiled into cdvp). It sees the paths between the pieces that the piece
// table (timing_model.h) does not, so a board's Fmax is the lesser of the two.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/resources/timing_model.h"

namespace cdvp {

// The whole board's path for a board, or why none is stored.
struct WholeBoardPath {
    std::optional<PathDelay> path;
    std::string missing;  // empty when path is set: "no whole-board timing of ..."
};

class WholeBoardTable {
public:
    // Parses the CSV that scripts/timing.sh --board-row prints; 'origin' names
    // it in errors. Throws std::invalid_argument "ORIGIN:LINE: ..." on a bad row.
    static WholeBoardTable parse(const std::string& csv, const std::string& origin);
    // The table compiled into cdvp (models/resources/whole_board_timing.csv).
    static const WholeBoardTable& stored();

    // The row of the board's top, family, speed grade, number format, compare
    // latency and pair FIFO memory; at an m between two stored points the
    // slower of the two, and of the stored address widths the narrowest that
    // holds the board's boxes (a wider board's counters and compares are no
    // shorter). A tiled board (boxes in SSRAM) has no row: its top is not
    // timed whole.
    WholeBoardPath path(const TimedBoard& board) const;

private:
    struct Row {
        std::string family, board, format;
        uint32_t m = 0;
        uint32_t compare_latency = 0;
        FifoMemory fifo_memory = FifoMemory::kBlockRam;
        uint32_t address_bits = 0;
        uint32_t speed_grade = 0;
        PathDelay path;
    };
    std::vector<Row> rows_;
};

}  // namespace cdvp
