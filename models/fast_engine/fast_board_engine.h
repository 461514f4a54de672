// The fast engine behind the board's engine seam (BoardEngine), so that
// BoardCore and its SystemC shell can run on it instead of the clocked datapath.
#pragma once

#include <cstdint>
#include <string>

#include "models/board/board_engine.h"
#include "models/fast_engine/fast_engine.h"

namespace cdvp {

// Answers every BoardEngine query as ClockedEngine does: the same segment
// ends, counters after any edge, buffer contents and abort. It keeps the
// current segment's buffer as a list (BoardEngine::buffer() hands out a
// PairList): at most the pair buffer's depth.
class FastBoardEngine : public BoardEngine {
public:
    explicit FastBoardEngine(const BoardConfig& config) : engine_(config) {}

    std::string name() const override { return "fast"; }
    void start(const CoordinateStore& store, uint32_t objects) override;
    void resume() override;
    void abort(uint64_t edges) override;
    uint64_t segment_edges() override { return end_edge_; }
    bool ended_by(uint64_t edges) override { return end_edge_ <= edges; }
    bool segment_finishes() override { return !aborted_ && engine_.phase() == BoardCore::Phase::Done; }
    SweepCounters counters_after(uint64_t edges) override;
    const PairList& buffer() override { return buffer_; }

    const FastEngine& engine() const { return engine_; }

private:
    // A new segment: its end, and the buffer it ends with.
    void begin_segment();

    FastEngine engine_;
    PairList buffer_;
    uint64_t end_edge_ = 0;
    bool aborted_ = false;
};

}  // namespace cdvp
