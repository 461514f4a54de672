#include "models/board/board_core.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace cdvp {

namespace {
CoordinateMemories make_memories(uint32_t m, uint32_t depth) {
    return {CoordinateMemory(m, depth), CoordinateMemory(m, depth), CoordinateMemory(m, depth),
            CoordinateMemory(m, depth), CoordinateMemory(m, depth), CoordinateMemory(m, depth)};
}
uint32_t low_word(uint64_t v) { return static_cast<uint32_t>(v); }
uint32_t high_word(uint64_t v) { return static_cast<uint32_t>(v >> 32); }
}  // namespace

BoardCore::BoardCore(const BoardConfig& config, uint32_t capacity)
    : config_((config.validate(), config)),
      capacity_(capacity),
      memories_(make_memories(config.m, capacity)),
      address_generator_(config.m),
      comparison_unit_(config.lanes(), config.compare),
      collector_(config.collector),
      line_(BlockRam::kReadLatencyCycles + config.compare.latency_cycles) {
    if (capacity > address_map::kMaxObjects) {
        throw std::invalid_argument("board capacity " + std::to_string(capacity) + " exceeds the address map's " +
                                    std::to_string(address_map::kMaxObjects) + " boxes");
    }
}

uint32_t BoardCore::block_rams() const { return kCoordinates * memories_[0].block_rams(); }

bool BoardCore::read_register(uint32_t offset, uint32_t& value) const {
    using R = ControlRegisters;
    switch (offset) {
        case R::kId: value = R::kIdValue; return true;
        case R::kControl: value = 0; return true;
        case R::kStatus: value = regs_.status(); return true;
        case R::kObjectCount: value = regs_.object_count; return true;
        case R::kPairCount: value = collector_.buffer_count(); return true;
        case R::kCyclesLo: value = low_word(regs_.cycles); return true;
        case R::kCyclesHi: value = high_word(regs_.cycles); return true;
        case R::kStallsLo: value = low_word(regs_.stalls); return true;
        case R::kStallsHi: value = high_word(regs_.stalls); return true;
        case R::kTotalPairsLo: value = low_word(collector_.total_pairs()); return true;
        case R::kTotalPairsHi: value = high_word(collector_.total_pairs()); return true;
        case R::kParallelism: value = config_.m; return true;
        case R::kCapacity: value = capacity_; return true;
        case R::kPairBufferDepth: value = collector_.buffer_depth(); return true;
        case R::kErrorCause: value = regs_.error_cause; return true;
        default: return false;
    }
}

BoardCore::Write BoardCore::write_register(uint32_t offset, uint32_t value) {
    using R = ControlRegisters;
    switch (offset) {
        case R::kObjectCount:
            // The sweep uses the count it started with; read-back must agree.
            if (regs_.busy) {
                raise_error(R::kWriteWhileBusy);
                return Write::kRefused;
            }
            regs_.object_count = value;
            return Write::kDone;
        case R::kControl:
            if (value & R::kAbort) abort();
            else if (value & R::kStart) start();
            else if (value & R::kResume) resume();
            else if (value & R::kAcknowledge) regs_.irq_pending = false;
            return Write::kDone;
        case R::kId: case R::kStatus: case R::kPairCount: case R::kCyclesLo: case R::kCyclesHi:
        case R::kStallsLo: case R::kStallsHi: case R::kTotalPairsLo: case R::kTotalPairsHi:
        case R::kParallelism: case R::kCapacity: case R::kPairBufferDepth: case R::kErrorCause:
            return Write::kDone;  // read-only: writes are ignored, as on the hardware
        default:
            return Write::kUnmapped;
    }
}

BoardCore::Write BoardCore::write_coordinate(Coordinate coordinate, uint32_t index, uint32_t word) {
    if (index >= capacity_) return Write::kUnmapped;
    if (regs_.busy) {
        raise_error(ControlRegisters::kWriteWhileBusy);
        return Write::kRefused;
    }
    memories_[coordinate].write(index, word);
    return Write::kDone;
}

uint32_t BoardCore::read_coordinate(Coordinate coordinate, uint32_t index) const {
    return memories_[coordinate].peek(index);
}

void BoardCore::raise_error(ControlRegisters::BoardError cause) {
    regs_.error = true;
    regs_.error_cause = cause;
    regs_.irq_pending = true;
}

// ABORT: the sweep stops where it is; the pair buffer keeps what it holds.
void BoardCore::abort() {
    phase_ = Phase::Idle;
    regs_.busy = regs_.done = regs_.overflow = regs_.error = regs_.irq_pending = false;
    regs_.error_cause = ControlRegisters::kNoError;
    stalled_ = false;
}

// START is refused (error bit) while a sweep is under way or when the object
// count exceeds the memories' depth; the previous results stay readable then.
void BoardCore::start() {
    if (regs_.busy || regs_.object_count > capacity_) {
        raise_error(regs_.busy ? ControlRegisters::kStartWhileBusy : ControlRegisters::kTooManyObjects);
        return;
    }
    address_generator_.start(regs_.object_count);
    collector_.reset();
    for (auto& slot : line_) slot = Slot{};
    head_ = 0;
    end_issued_ = end_seen_ = stalled_ = false;
    regs_.cycles = regs_.stalls = 0;
    regs_.busy = true;
    regs_.done = regs_.overflow = regs_.error = regs_.irq_pending = false;
    regs_.error_cause = ControlRegisters::kNoError;
    phase_ = Phase::Running;
}

// RESUME after an overflow: the host has read every buffered pair.
void BoardCore::resume() {
    if (phase_ != Phase::Paused) {
        raise_error(ControlRegisters::kResumeNotPaused);
        return;
    }
    collector_.clear_buffer();
    regs_.overflow = regs_.irq_pending = false;
    phase_ = Phase::Running;
}

BoardCore::Slot BoardCore::issue() {
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

void BoardCore::step() {
    ++regs_.cycles;
    if (collector_.drain_blocked()) {
        // A pair must move and the buffer is full: this edge does no work
        // (a stall) and the clock stops until the host drains and resumes.
        stalled_ = true;
        ++regs_.stalls;
        phase_ = Phase::Paused;
        regs_.overflow = regs_.irq_pending = true;
        return;
    }
    collector_.drain();
    if (end_seen_) {
        // Only the FIFO's last pairs are left to move: every such cycle is
        // beyond S + L, so it counts as a stall.
        stalled_ = true;
        ++regs_.stalls;
        if (collector_.fifo_level() == 0) finish();
        return;
    }
    Slot& leaving = line_[head_];
    if (leaving.kind == Slot::kSweep) {
        if (collector_.fifo_free() < static_cast<uint32_t>(__builtin_popcountll(leaving.hits))) {
            stalled_ = true;  // back-pressure: the whole pipeline holds this cycle
            ++regs_.stalls;
            return;
        }
        collector_.push(leaving.row, leaving.first_column, leaving.hits);
    } else if (leaving.kind == Slot::kEnd) {
        end_seen_ = true;
    }
    stalled_ = false;
    leaving = issue();
    head_ = head_ + 1 == line_.size() ? 0 : head_ + 1;
    if (end_seen_ && collector_.fifo_level() == 0) finish();
}

void BoardCore::finish() {
    phase_ = Phase::Done;
    regs_.busy = false;
    regs_.done = regs_.irq_pending = true;
}

}  // namespace cdvp
