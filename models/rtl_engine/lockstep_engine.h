// Lockstep: the RTL engine and the clocked engine stepped edge by edge side
// by side, compared after every edge, stopping at the first difference with
// the cycle and the signal that differ: from there on it steps the RTL alone
// and answers as the RTL does (the reference), so a platform run ends its
// frame and then reports the difference (BoardEngine::divergence()). The
// clocked engine is the board's: ClockedEngine, or GridClockedEngine for
// board.algorithm grid (whose grid registers are compared when a sweep is done).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "models/board_spec/board_engine.h"
#include "models/rtl_engine/rtl_engine.h"

namespace cdvp {

// The first difference: what() is one line naming the sweep's cycle, the
// segment's edge, the signal, and both values.
class LockstepDivergence : public std::runtime_error {
public:
    LockstepDivergence(uint64_t cycle, std::string signal, const std::string& what)
        : std::runtime_error(what), cycle_(cycle), signal_(std::move(signal)) {}
    uint64_t cycle() const { return cycle_; }
    const std::string& signal() const { return signal_; }

private:
    uint64_t cycle_;
    std::string signal_;
};

// What the check reads of the clocked engine after each edge (lockstep_engine.cpp
// adapts each board's clocked engine to it).
class LockstepModel {
public:
    virtual ~LockstepModel() = default;
    virtual BoardEngine& engine() = 0;
    virtual void advance_to(uint64_t edges) = 0;
    virtual uint64_t edges() const = 0;
    virtual SweepState state() const = 0;
    // The window the last edge issued, if it issued one.
    virtual std::optional<PortWindow> issued_window() const = 0;
    virtual uint64_t pushed_hits() const = 0;
    virtual uint32_t fifo_level() const = 0;
};

class LockstepEngine : public BoardEngine {
public:
    LockstepEngine(const BoardConfig& config, uint32_t capacity) : LockstepEngine(config, config, capacity) {}
    // The clocked model of one board against the RTL of another (a test of
    // the check itself: boards that differ must diverge).
    LockstepEngine(const BoardConfig& model, const BoardConfig& rtl, uint32_t capacity);
    ~LockstepEngine() override;

    std::string name() const override { return "rtl-lockstep"; }
    void start(const CoordinateStore& store, uint32_t objects) override;
    void resume() override;
    void abort(uint64_t edges) override;
    uint64_t segment_edges() override;
    bool ended_by(uint64_t edges) override;
    bool segment_finishes() override;
    SweepCounters counters_after(uint64_t edges) override;
    const IndexPair& buffer_entry(uint32_t k) override { return rtl_.buffer_entry(k); }
    std::string divergence() const override { return first_ ? first_->what() : std::string(); }
    GridSweepStats grid_stats() const override { return rtl_.grid_stats(); }

    // The first difference, or null while the two agree.
    const LockstepDivergence* first_divergence() const { return first_ ? &*first_ : nullptr; }
    // Edges compared so far, over every segment.
    uint64_t edges_compared() const { return compared_; }
    RtlEngine& rtl() { return rtl_; }

private:
    void advance_to(uint64_t edges);
    bool running() const;  // a model still in its segment (the RTL alone once they parted)
    void step();
    void compare_edge(const RtlProbes& before);
    void compare_grid_registers();
    void diverge(const std::string& signal, uint64_t rtl, uint64_t model);

    std::unique_ptr<LockstepModel> clocked_;
    RtlEngine rtl_;
    uint64_t compared_ = 0;
    uint64_t cycle_at_segment_start_ = 0;
    std::optional<LockstepDivergence> first_;
};

}  // namespace cdvp
