// What a board configuration costs on an FPGA, from real synthesis: the
// pieces that decide the cost (comparison lane per number format, address
// generator and pair FIFO per m, controller) were synthesised with Yosys
// (scripts/synthesize.sh; rows in synthesis.csv, compiled into cdvp), and a
// board adds them up the way it is built:
//   lanes x lane + coordinate memories + address generator + pair FIFO + control.
// The coordinate memories are block RAMs only (6 x m x ceil(N / 512)); the
// pair buffer lives in off-chip SSRAM and costs no FPGA resource. The grid
// board adds its binning stage's cell-function units and the one-cell filter
// (grid_board_resources); its block RAMs are the cell buffer's.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "models/resources/table_fields.h"

namespace cdvp {

// One piece's or one board's resources. LUTs count logic LUTs and the LUTs
// used as distributed RAM; block RAMs are 18 Kbit ones (a 36 Kbit block
// counts two).
struct Resources {
    double luts = 0;
    double flip_flops = 0;
    double carry_cells = 0;
    double block_rams = 0;
    double multipliers = 0;

    Resources& operator+=(const Resources& other);
    friend Resources operator+(Resources a, const Resources& b) { return a += b; }
    friend Resources operator*(double times, const Resources& r);
};

// The synthesis table: rows keyed by family (xc2v: Virtex-II; xcup: UltraScale+), piece and its
// parameters. Pieces synthesised at some m only are interpolated linearly
// in m between the two nearest rows (their cost is close to linear in the
// number of lanes between those points; the table records every row).
class SynthesisTable {
public:
    // Parses the CSV that scripts/synthesize.sh prints; 'origin' names it in
    // errors. Throws std::invalid_argument "ORIGIN:LINE: ..." on a bad row.
    static SynthesisTable parse(const std::string& csv, const std::string& origin);
    // The table compiled into cdvp (models/resources/synthesis.csv).
    static const SynthesisTable& stored();

    // Throws std::invalid_argument naming what is missing.
    Resources lane(const std::string& family, const std::string& format) const;
    Resources address_generator(const std::string& family, uint32_t m) const;
    // memory: where the FIFO's entries live, "block_ram" or "distributed".
    Resources pair_collector(const std::string& family, uint32_t m, const std::string& memory) const;
    Resources control(const std::string& family) const;
    // The grid board's pieces: one cell-function unit in a number format
    // (fixedK between two synthesised widths interpolated in K), the
    // one-cell filter of an m board's 2m-1 lanes.
    Resources cell_function(const std::string& family, const std::string& format) const;
    Resources home_cell_filter(const std::string& family, uint32_t m) const;
    // The binning sequencer's own logic (its cell-function units and cell
    // memory apart): the one row synthesised, float32 at m = 8 and 2^16
    // boxes, for every grid board (its passes, counters and setup arithmetic
    // hardly depend on m, the format or the boxes' bits: docs/grid_board.md).
    Resources grid_sequencer(const std::string& family) const;
    std::vector<std::string> families() const;
    std::vector<std::string> formats(const std::string& family) const;

private:
    struct Row : TableRowKey {
        Resources resources;
    };
    const Row* find(std::string_view family, std::string_view piece, std::string_view format) const;
    Resources by_m(std::string_view family, std::string_view piece, std::string_view format, uint32_t m) const;
    // The rows of a family, piece and format (indices into rows_), or null.
    const std::vector<std::size_t>* rows_of(std::string_view family, std::string_view piece,
                                            std::string_view format) const;
    std::vector<Row> rows_;
    // The rows of each family, piece and format, found without building a
    // string (a device fit looks up every piece at every m).
    std::map<std::tuple<std::string, std::string, std::string>, std::vector<std::size_t>, std::less<>> by_key_;
};

// A device's capacities, with where they come from.
struct DeviceCapacity {
    std::string name;    // e.g. XC2V6000
    std::string family;  // the synthesis family: xc2v or xcup
    double luts = 0;
    double flip_flops = 0;
    double block_rams = 0;  // 18 Kbit
    std::string source;
};

// How the block RAMs of a board's box memories are arranged, and which of
// them a cycle enables. A Xilinx block RAM draws its dynamic power on the
// cycles its port enable (ENA/ENB) is high (Virtex-II UG002, UltraScale
// UG573); a memory cascaded in depth decodes its address's high bits into
// the enable of one block (the Block Memory Generator's low-power
// algorithm, PG058), so a read or a write enables one block of each
// cascade, not the cascade. A copy's six coordinates share one enable
// (models/board/rtl: coordinate_copy), so a cycle enables every word group
// of the copies it reads or writes.
struct BlockRamGeometry {
    uint64_t word_groups = 0;   // primitives side by side for a box's six coordinates
    uint64_t depth_blocks = 0;  // primitives cascaded in depth: ceil(depth / words a primitive)
    uint64_t copies = 0;        // copies a compare cycle enables (a bank's m; both tile buffers or cell halves)
    uint64_t banks = 1;         // banks of those copies, one swept while the host writes another
    // Whether the host's upload writes these memories (the boxes in block
    // RAM) or not (a tiled or grid board keeps its boxes in SSRAM; its
    // loader writes the buffers on cycles they are enabled for the lanes).
    bool uploaded = true;

    uint64_t block_rams() const { return banks * copies * word_groups * depth_blocks; }
    // A compare cycle: every word group of every copy, one block of each
    // cascade; none when the memories hold no block (a board for no boxes).
    uint64_t read_enabled() const { return depth_blocks > 0 ? copies * word_groups : 0; }
    // An upload write cycle: every copy of the bank written, one block of each cascade.
    uint64_t write_enabled() const { return uploaded ? read_enabled() : 0; }
};

// Where the pair FIFO lives: a block RAM when one is left beside the boxes,
// else LUTs as distributed RAM.
enum class FifoMemory { kBlockRam, kDistributed };
// The synthesis tables' and the report's word for it: "block_ram", "distributed".
const char* fifo_memory_name(FifoMemory memory);

// A board's resources by piece.
struct BoardResources {
    Resources lanes;  // all 2m-1 of them
    Resources coordinate_memories;
    Resources address_generator;
    Resources pair_collector;
    FifoMemory pair_fifo_memory = FifoMemory::kBlockRam;
    Resources control;
    // The grid board's cell-function units, one-cell filter and binning
    // sequencer (none on the all-pairs board).
    Resources grid_blocks;
    // What the block RAMs of coordinate_memories hold: "the boxes", or the
    // grid board's "the cell buffer" (a cell's boxes at a time).
    const char* memories_hold = "the boxes";
    // The arrangement of coordinate_memories' block RAMs (BoardConfig::block_ram_geometry).
    BlockRamGeometry memory_geometry;
    Resources total() const {
        return lanes + coordinate_memories + address_generator + pair_collector + control + grid_blocks;
    }
};

// 'memory_block_rams': the coordinate memories' block RAMs
// (BoardConfig::block_rams(capacity)). The pair FIFO goes to block RAM when
// the device has block RAMs left beside the coordinate memories, else to
// distributed RAM (LUTs), as a designer would place it.
BoardResources board_resources(const SynthesisTable& table, const DeviceCapacity& device, const std::string& format,
                               uint32_t m, double memory_block_rams);

// The grid board (docs/grid_board.md): the all-pairs board's lanes,
// address generator, pair FIFO and controller around its cell buffer
// ('cell_buffer_block_rams', BoardConfig::block_rams), plus the binning
// stage's cell-function units (kCellFunctionUnits: one a bound of a box,
// shared by the binning passes and the cell loader, which never run at once),
// the one-cell filter and the binning sequencer's logic (its row). Its cell
// memory is the board's SSRAM: no logic counted for it.
BoardResources grid_board_resources(const SynthesisTable& table, const DeviceCapacity& device,
                                    const std::string& format, uint32_t m, double cell_buffer_block_rams);
constexpr uint32_t kCellFunctionUnits = 6;

// How a board's resources sit on a device: utilisation of each resource
// (used / available) and the first one that overflows, if any.
struct Utilisation {
    double luts = 0, flip_flops = 0, block_rams = 0;
    // "" when everything fits, else "LUTs", "flip-flops" or "block RAMs".
    std::string overflow;
    bool fits() const { return overflow.empty(); }
};
Utilisation utilisation(const Resources& used, const DeviceCapacity& device);

}  // namespace cdvp
