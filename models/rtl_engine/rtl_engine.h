// The RTL engine: the whole-board RTL (models/board/rtl/collision_board_top.v,
// or grid_board_top.v for a grid board), compiled by Verilator, behind the
// BoardEngine seam. BoardCore keeps the host's registers and stores; at
// START this engine writes the boxes that changed into the RTL's coordinate
// memories over the RTL's own register bus (a tiled or grid board's SSRAM
// directly), writes OBJECT_COUNT and START, and clocks the RTL edge by edge:
// its counters, state and the pairs entering its pair buffer are what
// counters_after() and buffer_entry() answer. Like the clocked engine it may
// step a segment ahead in bulk and answer for earlier edges.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "models/board_spec/board_engine.h"
#include "models/board_spec/segment_history.h"
#include "models/rtl_engine/rtl_board.h"
#include "models/rtl_engine/rtl_variant.h"

namespace cdvp {

class RtlEngine : public BoardEngine {
public:
    // Throws as rtl_variant_for() does when no variant can serve the board.
    RtlEngine(const BoardConfig& config, uint32_t capacity);
    ~RtlEngine() override;

    std::string name() const override { return "rtl"; }
    void start(const CoordinateStore& store, uint32_t objects) override;
    void resume() override;
    void abort(uint64_t edges) override;
    uint64_t segment_edges() override;
    bool ended_by(uint64_t edges) override {
        advance_to(edges);
        return state_ != SweepState::kRunning && edges_ <= edges;
    }
    bool segment_finishes() override;
    SweepCounters counters_after(uint64_t edges) override;
    const IndexPair& buffer_entry(uint32_t k) override { return pairs_[k]; }
    // A grid board's last sweep, as its grid registers keep it.
    GridSweepStats grid_stats() const override;

    // Steps the RTL to `edges` edges of the segment, or to its end.
    void advance_to(uint64_t edges);
    uint64_t edges() const { return edges_; }
    SweepState state() const { return state_; }
    // The RTL's signals after the last edge (for a lockstep check).
    const RtlProbes& probes() const { return probes_; }
    const RtlVariant& variant() const { return variant_; }

    // Waveforms of the RTL's own signals into `path` (Verilator's VCD, in
    // femtoseconds). Each command's edge is placed at the time
    // `command_time_fs` gives when the engine takes it (the shell's simulated
    // time), later edges one period apart.
    void trace_to(const std::string& path, std::function<uint64_t()> command_time_fs);
    void set_trace_open(bool open) { board_->set_trace_open(open); }
    void flush_trace() { board_->flush_trace(); }
    void close_trace() { board_->close_trace(); }

private:
    void step();
    void command(uint32_t control);
    void upload(const CoordinateStore& store, uint32_t objects);

    BoardConfig config_;
    RtlVariant variant_;
    std::unique_ptr<RtlBoard> board_;
    uint64_t period_fs_;
    std::function<uint64_t()> command_time_fs_;
    // What the RTL's coordinate memories hold (kUnknown before the first write).
    static constexpr uint64_t kUnknown = uint64_t{1} << 32;
    std::array<std::vector<uint64_t>, kCoordinates> loaded_;

    SweepState state_ = SweepState::kIdle;
    uint64_t edges_ = 0;
    RtlProbes probes_;
    SegmentHistory history_;
    std::vector<IndexPair> pairs_;  // the pair buffer's entries this segment
};

}  // namespace cdvp
