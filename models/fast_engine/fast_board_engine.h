// The fast engine behind the board's engine seam (BoardEngine), so that
// BoardCore and its SystemC shell can run on it instead of the clocked datapath.
#pragma once

#include <cstdint>
#include <string>

#include "models/board_spec/board_engine.h"
#include "models/fast_engine/fast_engine.h"

namespace cdvp {

// Answers every BoardEngine query as ClockedEngine does: the same segment
// ends, counters after any edge, buffer contents and abort.
class FastBoardEngine : public BoardEngine {
public:
    explicit FastBoardEngine(const BoardConfig& config, PairBudget budget = {}) : engine_(config, budget) {}

    std::string name() const override { return "fast"; }
    void start(const CoordinateStore& store, uint32_t objects) override;
    void resume() override;
    void abort(uint64_t edges) override;
    uint64_t segment_edges() override { return end_edge_; }
    bool ended_by(uint64_t edges) override { return end_edge_ <= edges; }
    bool segment_finishes() override { return !aborted_ && engine_.phase() == SweepState::kDone; }
    SweepCounters counters_after(uint64_t edges) override;
    const IndexPair& buffer_entry(uint32_t k) override { return engine_.buffer_entry(k); }

    const FastEngine& engine() const { return engine_; }

private:
    // A new segment: where it ends.
    void begin_segment();

    FastEngine engine_;
    uint64_t end_edge_ = 0;
    bool aborted_ = false;
};

}  // namespace cdvp
