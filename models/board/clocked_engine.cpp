#include "models/board/clocked_engine.h"

#include <algorithm>

namespace cdvp {

namespace {
CoordinateMemories make_memories(uint32_t m, uint32_t depth, uint32_t words_per_primitive) {
    const CoordinateMemory memory(m, depth, words_per_primitive);
    return {memory, memory, memory, memory, memory, memory};
}
}  // namespace

ClockedEngine::ClockedEngine(const BoardConfig& config, uint32_t capacity)
    : config_(config),
      memories_(make_memories(config.m, capacity, config.format.boxes_per_block_ram())),
      address_generator_(config.m),
      comparison_unit_(config.lanes(), config.compare, config.format),
      collector_(config.collector),
      line_(BlockRam::kReadLatencyCycles + config.compare.latency_cycles) {}

void ClockedEngine::start(const CoordinateStore& store, uint32_t objects) {
    // The host's writes reach every copy of the block RAMs; loading them here
    // is the same, as nothing reads them before the sweep.
    for (uint32_t c = 0; c < kCoordinates; ++c) {
        for (uint32_t i = 0; i < objects; ++i) memories_[c].write(i, store[c][i]);
    }
    address_generator_.start(objects);
    collector_.reset();
    for (auto& slot : line_) slot = Slot{};
    head_ = 0;
    end_issued_ = end_seen_ = stalled_ = false;
    at_segment_start_ = SweepCounters{};
    edges_ = 0;
    buffered_at_.clear();
    pushed_at_.clear();
    stall_runs_.clear();
    state_ = State::kRunning;
}

void ClockedEngine::resume() {
    at_segment_start_ = counters_after(edges_);
    at_segment_start_.buffered = 0;
    collector_.clear_buffer();
    edges_ = 0;
    buffered_at_.clear();
    pushed_at_.clear();
    stall_runs_.clear();
    state_ = State::kRunning;
}

void ClockedEngine::abort(uint64_t edges) {
    advance_to(edges);
    collector_.truncate_buffer(counters_after(edges).buffered);
    state_ = State::kIdle;
}

uint64_t ClockedEngine::segment_edges() {
    while (state_ == State::kRunning) step();
    return edges_;
}

bool ClockedEngine::segment_finishes() {
    segment_edges();
    return state_ == State::kDone;
}

void ClockedEngine::advance_to(uint64_t edges) {
    while (state_ == State::kRunning && edges_ < edges) step();
}

uint64_t ClockedEngine::stalls_through(uint64_t edges) const {
    // The last run that began at or before `edges`.
    auto after = std::upper_bound(stall_runs_.begin(), stall_runs_.end(), edges,
                                  [](uint64_t e, const StallRun& run) { return e < run.first_edge; });
    if (after == stall_runs_.begin()) return 0;
    const StallRun& run = *(after - 1);
    return run.stalls_before + std::min(run.length, edges - run.first_edge + 1);
}

SweepCounters ClockedEngine::counters_after(uint64_t edges) {
    advance_to(edges);
    edges = std::min(edges, edges_);
    auto through = [edges](const std::vector<uint64_t>& at) {
        return static_cast<uint64_t>(std::upper_bound(at.begin(), at.end(), edges) - at.begin());
    };
    SweepCounters c = at_segment_start_;
    c.cycles += edges;
    c.stalls += stalls_through(edges);
    c.buffered = static_cast<uint32_t>(through(buffered_at_));
    c.total_pairs += through(pushed_at_);
    return c;
}

ClockedEngine::Slot ClockedEngine::issue() {
    if (address_generator_.exhausted()) {
        if (end_issued_) return Slot{};
        end_issued_ = true;
        return Slot{Slot::kEnd};
    }
    const AddressGenerator::Issue addresses = address_generator_.current();
    last_issue_ = addresses;
    for (auto& memory : memories_) {
        memory.clock_read(0, addresses.row);
        for (uint32_t lane = 0; lane < addresses.valid_lanes; ++lane) {
            memory.clock_read(lane + 1, addresses.first_column + lane);
        }
    }
    address_generator_.advance();
    // The hit mask is a pure function of the block RAM output registers just
    // loaded, so computing it here and presenting it compare-latency cycles
    // later is the same as computing it in the last compare stage.
    return Slot{Slot::kSweep, addresses.row, addresses.first_column, addresses.valid_lanes,
                comparison_unit_.evaluate(memories_, addresses.valid_lanes)};
}

void ClockedEngine::stall() {
    stalled_ = true;
    if (!stall_runs_.empty() && stall_runs_.back().first_edge + stall_runs_.back().length == edges_) {
        ++stall_runs_.back().length;
        return;
    }
    const uint64_t before = stall_runs_.empty() ? 0 : stall_runs_.back().stalls_before + stall_runs_.back().length;
    stall_runs_.push_back({edges_, 1, before});
}

// One clock edge; every edge counts as a cycle. An edge that finds the pair
// buffer full pauses the board (and counts as a stall).
void ClockedEngine::step() {
    ++edges_;
    if (collector_.drain_blocked()) {
        // A pair must move and the buffer is full: this edge does no work
        // (a stall) and the clock stops until the host drains and resumes.
        stall();
        state_ = State::kPaused;
        return;
    }
    const uint32_t before = collector_.buffer_count();
    collector_.drain();
    buffered_at_.insert(buffered_at_.end(), collector_.buffer_count() - before, edges_);
    if (end_seen_) {
        // Only the FIFO's last pairs are left to move: every such cycle is
        // beyond S + L, so it counts as a stall.
        stall();
        if (collector_.fifo_level() == 0) state_ = State::kDone;
        return;
    }
    Slot& leaving = line_[head_];
    if (leaving.kind == Slot::kSweep) {
        const auto hits = static_cast<uint32_t>(__builtin_popcountll(leaving.hits));
        if (collector_.fifo_free() < hits) {
            stall();  // back-pressure: the whole pipeline holds this cycle
            return;
        }
        collector_.push(leaving.row, leaving.first_column, leaving.hits);
        pushed_at_.insert(pushed_at_.end(), hits, edges_);
    } else if (leaving.kind == Slot::kEnd) {
        end_seen_ = true;
    }
    stalled_ = false;
    leaving = issue();
    head_ = head_ + 1 == line_.size() ? 0 : head_ + 1;
    if (end_seen_ && collector_.fifo_level() == 0) state_ = State::kDone;
}

}  // namespace cdvp
