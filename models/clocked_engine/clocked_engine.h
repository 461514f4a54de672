// The clocked engine: the seed's datapath stepped one clock edge at a time.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "models/address_generator/address_generator.h"
#include "models/address_generator/sweep_schedule.h"
#include "models/board_spec/board_engine.h"
#include "models/clocked_engine/slot_pipeline.h"
#include "models/coordinate_memory/coordinate_memory.h"
#include "models/tile_loader/tile_loader.h"

namespace cdvp {

// Wires the blocks of the seed's microarchitecture:
//   address generator -> six 2m-port coordinate memories (1 cycle)
//   -> comparison unit (compare latency) -> pair FIFO -> pair buffer.
// On a tiled board (config.tiles) the boxes sit in SSRAM and the address
// generator walks the tiled schedule (SweepSchedule): port 0 reads a
// double-buffered row memory, ports 1..2m-1 a double-buffered column memory,
// and the loader (TileLoader) brings the next block's tile from SSRAM into
// the idle buffer while the other is compared; the address generator issues
// bubbles until it has landed.
// Nothing outside the board sees it between host accesses, so a segment may
// be stepped ahead in bulk (segment_edges()) while what each edge changed is
// kept: counters_after() then answers for any earlier edge. For waveforms the
// shell steps it edge by edge instead (advance_to()) and reads the probes.
class ClockedEngine : public BoardEngine {
public:
    // What travels down the pipeline: the row, the first column and the valid
    // lanes of one address-generator cycle, with the lane hits once compared.
    struct Slot {
        enum Kind : uint8_t { kBubble, kSweep, kEnd } kind = kBubble;
        PortWindow window;
        uint64_t hits = 0;
        uint32_t hit_count() const { return static_cast<uint32_t>(__builtin_popcountll(hits)); }
    };

    // capacity: the coordinate memories' depth in boxes.
    ClockedEngine(const BoardConfig& config, uint32_t capacity);

    std::string name() const override { return "cycle"; }
    void start(const CoordinateStore& store, uint32_t objects) override;
    void resume() override;
    void abort(uint64_t edges) override;
    uint64_t segment_edges() override;
    bool ended_by(uint64_t edges) override {
        advance_to(edges);
        return state() != SweepState::kRunning && this->edges() <= edges;
    }
    bool segment_finishes() override;
    SweepCounters counters_after(uint64_t edges) override;
    const IndexPair& buffer_entry(uint32_t k) override { return pipeline_.collector().buffer_entry(k); }

    // Steps the datapath to `edges` edges of the segment, or to its end.
    void advance_to(uint64_t edges);

    // Probes for waveforms: the last edge's addresses, compare output and stall;
    // on a tiled board the block's row and column tiles, whether a tile is
    // loading and whether the address generator waits for one.
    const PortWindow& last_issue() const { return last_issue_; }
    uint32_t row_tile() const { return tile_of(false); }
    uint32_t column_tile() const { return tile_of(true); }
    bool loading() const { return loader_ != nullptr && loader_->busy(); }
    bool waiting() const { return waiting_; }
    const Slot& compare_output() const { return pipeline_.compare_output(); }
    bool stalled() const { return pipeline_.stalled(); }
    // The last edge's slot issued into the pipeline (a bubble when none was:
    // every edge that does not issue stalls) and the lane hits it pushed
    // into the FIFO (0 when none). Derived, so the edge itself pays nothing.
    const Slot& issued() const {
        const Slot* slot = pipeline_.issued();
        return slot != nullptr ? *slot : kNoSlot;
    }
    uint64_t pushed_hits() const { return pipeline_.pushed_this_edge() ? pushed_hits_ : 0; }
    SweepState state() const { return pipeline_.state(); }
    uint64_t edges() const { return pipeline_.edges(); }
    uint32_t fifo_level() const { return pipeline_.collector().fifo_level(); }
    // Block RAM primitives of the six coordinate memories (or tile buffers).
    uint32_t block_rams() const;

private:
    void step();
    Slot issue();
    uint32_t tile_of(bool column) const;

    BoardConfig config_;
    // Untiled: one set of coordinate memories for every box. Tiled: the
    // loader with the SSRAM and the tile buffers.
    std::vector<CoordinateMemories> memories_;
    BlockRamLayout layout_;  // of memories_
    std::unique_ptr<TileLoader> loader_;
    SweepSchedule schedule_;
    ScheduleWalker walker_{schedule_};
    uint64_t loads_begun_ = 0;
    uint64_t block_ = 0;  // the block of the last issued slot
    bool waiting_ = false;
    ComparisonUnit comparison_unit_;
    // Block RAM stage plus compare stages, then the pair collector.
    SlotPipeline<Slot> pipeline_;
    bool end_issued_ = false;  // the address generator sent its end marker
    uint64_t pushed_hits_ = 0;  // the last push's lane hits
    static const Slot kNoSlot;
    PortWindow last_issue_{};
};

}  // namespace cdvp
