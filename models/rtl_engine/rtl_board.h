// The board RTL as compiled by Verilator, seen from C++: one clock edge at a
// time, the host register bus, the behavioural SSRAM of a tiled board, the
// signals an engine and a lockstep check read after each edge, and tracing.
// VerilatedBoard (verilated_board.h) implements it for each variant, built in
// or compiled on first use into a shared object (rtl_model_cache.h): this
// header is compiled into those too, so it includes only the standard
// library and models/common/aabb.h (the RTL kit that `cmake --install` ships).
#pragma once

#include <cstdint>
#include <string>

#include "models/common/aabb.h"

namespace cdvp {

// What the C++ side of a Verilated model needs of its parameters (the others
// are the RTL's alone): how the pair and the SSRAM are addressed.
struct RtlMemoryShape {
    uint32_t address_bits = 9;  // AW: 2^AW boxes
    uint32_t tile_boxes = 0;    // TILE_BOXES (0: block RAM, no SSRAM)
    uint32_t tile_latency = 2;  // TILE_LATENCY
    // 1: the grid board's top (grid_board_top.v): its boxes in SSRAM, which
    // answers in its address's cycle (the top holds the read latency).
    uint32_t grid = 0;

    uint64_t capacity() const { return uint64_t{1} << address_bits; }
    bool has_ssram() const { return tile_boxes > 0 || grid != 0; }
    uint32_t ssram_latency() const { return grid != 0 ? 0 : tile_latency; }
};

// What the RTL shows after a rising edge.
struct RtlProbes {
    uint8_t state = 0;          // board_control's one-hot state: idle, sweep, drain, paused, done
    uint64_t cycles = 0;        // CYCLES
    uint64_t stalls = 0;        // STALLS
    uint64_t total_pairs = 0;   // TOTAL_PAIRS
    uint32_t buffered = 0;      // PAIR_COUNT
    uint32_t fifo_level = 0;    // pairs in the pair FIFO
    bool pair_valid = false;    // a pair entered the pair buffer at this edge
    IndexPair pair{};           // which (row, column)
    bool enable = false;        // the pipeline advances at the next edge
    bool window = false;        // and issues a window of boxes (not a bubble):
    uint32_t row = 0;           // port 0's box,
    uint32_t first_column = 0;  // port 1's box,
    uint64_t valid_lanes = 0;   // and the lanes with a box (a mask)
    uint64_t hits = 0;          // lane hits the next edge pushes into the FIFO
    // The grid board's last sweep, as its grid registers keep it (GridSweepStats).
    uint32_t grid_dims = 0, grid_large = 0, grid_overflow = 0, grid_excluded = 0, grid_busy = 0;
    uint64_t grid_entries = 0, grid_slots = 0;

    static constexpr uint8_t kIdle = 1, kSweep = 2, kDrain = 4, kPaused = 8, kDone = 16;
};

class RtlBoard {
public:
    virtual ~RtlBoard() = default;

    // One clock period: the rising edge, the SSRAM's answer, the falling edge.
    virtual void edge() = 0;
    // A host bus write (one clock period with the write strobe).
    virtual void write(uint32_t address, uint32_t data) = 0;
    // A tiled board's SSRAM bank `coordinate`, word `index`, loaded directly
    // (the board passes host writes through to it unchanged).
    virtual void load_ssram(uint32_t coordinate, uint32_t index, uint32_t word) = 0;
    // The signals after the last edge.
    virtual RtlProbes probes() const = 0;

    // Waveforms of every RTL signal into a VCD file in femtoseconds, the
    // platform's unit (before the first edge that should appear); each later
    // edge is dumped at the time set_time_fs() gave plus one period an edge.
    virtual void trace_to(const std::string& path, uint64_t period_fs) = 0;
    virtual void set_time_fs(uint64_t time_fs) = 0;
    // Closed: edges step without being dumped (a window of traced frames);
    // reopened, the next dump writes what changed meanwhile.
    virtual void set_trace_open(bool open) = 0;
    virtual void flush_trace() = 0;
    virtual void close_trace() = 0;
};

// The C entry point of a model compiled into a shared object (and the
// signature of a built-in variant's maker): a new board of that model, owned
// by the caller. rtl_model_entry.cpp.in defines it.
using RtlBoardMaker = RtlBoard* (*)(const RtlMemoryShape* shape);
constexpr const char* kRtlBoardMakerSymbol = "cdvp_rtl_make_board";

}  // namespace cdvp
