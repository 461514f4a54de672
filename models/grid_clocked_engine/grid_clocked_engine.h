// The grid board's clocked engine: its blocks stepped one clock edge at a
// time (docs/grid_board.md). A sequencer walks the passes slot by slot and
// moves the data: the bounds unit (GridBounds), the binning stage's cell
// function and classification (GridGeometry), the cell memory (CellTable),
// the double-buffered cell buffer and its loader (CellBuffer), the 2m-1
// lanes with the one-cell rule, and the seed's pipeline and pair collector
// (SlotPipeline). Nothing outside the board sees it between host accesses,
// so a segment may be stepped ahead in bulk while each edge is kept.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "models/board_spec/board_engine.h"
#include "models/cell_memory/cell_buffer.h"
#include "models/cell_memory/cell_table.h"
#include "models/clocked_engine/slot_pipeline.h"
#include "models/grid_binning/grid_geometry.h"

namespace cdvp {

class GridClockedEngine : public BoardEngine {
public:
    // What travels down the pipeline: the window issued (cell buffer
    // positions; in the large sweep the row is the streamed box), its lane
    // hits and the box pairs they make, in lane order.
    struct Slot {
        enum Kind : uint8_t { kBubble, kSweep, kEnd } kind = kBubble;
        PortWindow window;
        uint64_t hits = 0;
        uint32_t count = 0;
        std::array<IndexPair, ComparisonUnit::kMaxLanes> pairs;
        uint32_t hit_count() const { return count; }
    };
    // The sequencer's passes, in order (the waveforms name them so).
    enum class Pass : uint8_t { kIdle, kBounds, kSetup, kCount, kScan, kPlace, kCells, kLarge, kEnd };
    static constexpr uint32_t kPasses = 9;

    // capacity: the boxes the box store holds.
    GridClockedEngine(const BoardConfig& config, uint32_t capacity);

    std::string name() const override { return "cycle"; }
    void start(const CoordinateStore& store, uint32_t objects) override;
    void resume() override { pipeline_.resume(); }
    void abort(uint64_t edges) override {
        advance_to(edges);
        pipeline_.abort(edges);
    }
    uint64_t segment_edges() override;
    bool ended_by(uint64_t edges) override {
        advance_to(edges);
        return pipeline_.state() != SweepState::kRunning && pipeline_.edges() <= edges;
    }
    bool segment_finishes() override;
    SweepCounters counters_after(uint64_t edges) override {
        advance_to(edges);
        return pipeline_.counters_after(edges);
    }
    const IndexPair& buffer_entry(uint32_t k) override { return pipeline_.collector().buffer_entry(k); }
    GridSweepStats grid_stats() const override { return stats_; }

    // Steps to `edges` edges of the segment, or to its end.
    void advance_to(uint64_t edges);

    // Probes for waveforms: the pass, the box it is at (binning, or the
    // streamed box), the busy cell swept (its number), the large tile, whether
    // the loader is busy and whether the lanes wait for it; the datapath as
    // the seed's engine shows it.
    Pass pass() const { return pass_; }
    uint32_t box() const { return box_; }
    uint32_t cell() const { return cell_number_; }
    uint32_t tile() const { return tile_; }
    bool loading() const { return buffer_.loading(); }
    bool waiting() const { return waiting_; }
    const PortWindow& last_issue() const { return last_issue_; }
    const Slot& compare_output() const { return pipeline_.compare_output(); }
    bool stalled() const { return pipeline_.stalled(); }
    // The last edge's slot issued into the pipeline (a bubble when none was)
    // and the lane hits, after the one-cell rule, it pushed into the FIFO (0
    // when none): what the lockstep check holds the RTL to.
    const Slot& issued() const {
        const Slot* slot = pipeline_.issued();
        return slot != nullptr ? *slot : kNoSlot;
    }
    uint64_t pushed_hits() const { return pipeline_.pushed_this_edge() ? pushed_hits_ : 0; }
    uint32_t fifo_level() const { return pipeline_.collector().fifo_level(); }
    SweepState state() const { return pipeline_.state(); }
    uint64_t edges() const { return pipeline_.edges(); }

private:
    void step();
    // The front end's slot: the sequencer's next window, bubble or end marker.
    Slot issue();
    // Each pass's slot; a pass that ends moves the sequencer on (enter()).
    Slot bounds_slot();
    Slot setup_slot();
    Slot bin_slot(bool place);
    Slot scan_slot();
    Slot cells_slot();
    Slot large_slot();
    void enter(Pass pass);
    // The next box of a pass: its slots (q, or its cells when more).
    void next_box(bool place);
    void commit_box(bool place);
    void begin_tile();
    // Box i's keys and whether a word of it is excluded.
    bool keys_of(uint32_t i, uint32_t (&keys)[kCoordinates]) const;
    // The lanes over the cell buffer: a cell's window, or the streamed row's.
    Slot read_window(CoordinateMemories& rows, uint32_t row_address, CoordinateMemories& columns,
                     const PortWindow& window);
    Slot compare_cell(uint32_t half, const PortWindow& window);
    Slot compare_row(const PortWindow& window);

    BoardConfig config_;
    GridSlots slots_;
    CellBuffer buffer_;
    ComparisonUnit lanes_;
    CoordinateMemories row_register_;  // the streamed box (port 0)
    SlotPipeline<Slot> pipeline_;
    const CoordinateStore* store_ = nullptr;  // the SSRAM box store, as the host wrote it
    uint32_t objects_ = 0;

    // The binning stage and cell memory.
    GridBounds bounds_;
    GridGeometry grid_;
    CellTable table_;
    enum Kind : uint8_t { kBinned, kLarge, kExcluded };
    std::vector<uint8_t> kind_;    // per box, from pass 2
    std::vector<uint32_t> large_;  // ascending
    GridSweepStats stats_;

    // The sequencer.
    Pass pass_ = Pass::kIdle;
    uint64_t pass_slot_ = 0;   // slots into the pass
    uint32_t box_ = 0;         // the pass's box
    uint64_t box_left_ = 0;    // its slots left
    CellRange range_;          // its cells
    uint64_t box_cells_ = 0;   // 0 unless a candidate
    // Cells: the busy cell swept and loaded; the triangle's row and column.
    uint32_t block_ = 0, blocks_loaded_ = 0;
    bool in_block_ = false, waiting_ = false;
    uint32_t row_ = 0, column_ = 0;
    uint32_t cell_number_ = 0;
    // Large: the tile, its load, the streamed box's columns.
    uint32_t tile_ = 0, tile_begin_ = 0, tile_count_ = 0, rank_ = 0;
    uint32_t first_column_ = 0, columns_left_ = 0;
    bool end_issued_ = false;
    uint64_t slots_issued_ = 0;
    uint64_t pushed_hits_ = 0;  // the last push's lane hits
    static const Slot kNoSlot;
    PortWindow last_issue_{};
};

const char* to_string(GridClockedEngine::Pass pass);

}  // namespace cdvp
