// A result-oriented engine behind the board's engine seam (BoardEngine): an
// engine that finds a sweep's pairs and replays its timeline (FastEngine for
// the seed's board, GridFastEngine for the grid board) answers every query
// as the clocked engine does, so that BoardCore and its SystemC shell can run
// on it instead of stepping the datapath.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include "models/board_spec/board_engine.h"
#include "models/fast_engine/pair_finder.h"

namespace cdvp {

// Engine: start(objects, CoordinateWords), resume(), segment_cycles(),
// observe(edges) -> BoardObservation, phase(), buffer_entry(k).
template <class Engine>
class ResultBoardEngine : public BoardEngine {
public:
    template <class... Args>
    explicit ResultBoardEngine(Args&&... args) : engine_(std::forward<Args>(args)...) {}

    std::string name() const override { return "fast"; }
    void start(const CoordinateStore& store, uint32_t objects) override {
        CoordinateWords words{};
        for (uint32_t c = 0; c < kCoordinates; ++c) words[c] = store[c].data();
        engine_.start(objects, words);
        begin_segment();
    }
    void resume() override {
        engine_.resume();
        begin_segment();
    }
    // The sweep stops at that edge (or where the segment ended before it); the
    // buffer keeps what it held then (the board reads only that many entries).
    void abort(uint64_t edges) override {
        end_edge_ = std::min(edges, end_edge_);
        aborted_ = true;
    }
    uint64_t segment_edges() override { return end_edge_; }
    bool ended_by(uint64_t edges) override { return end_edge_ <= edges; }
    bool segment_finishes() override { return !aborted_ && engine_.phase() == SweepState::kDone; }
    SweepCounters counters_after(uint64_t edges) override {
        const auto seen = engine_.observe(std::min(edges, end_edge_));
        SweepCounters counters;
        counters.cycles = seen.cycles;
        counters.stalls = seen.stalls;
        counters.buffered = seen.buffer_count;
        counters.total_pairs = seen.total_pairs;
        return counters;
    }
    const IndexPair& buffer_entry(uint32_t k) override { return engine_.buffer_entry(k); }

    const Engine& engine() const { return engine_; }

protected:
    Engine engine_;

private:
    // A new segment: where it ends.
    void begin_segment() {
        end_edge_ = engine_.segment_cycles();
        aborted_ = false;
    }

    uint64_t end_edge_ = 0;
    bool aborted_ = false;
};

}  // namespace cdvp
