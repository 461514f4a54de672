// The board's datapath and control as plain C++: one step() per clock edge.
#pragma once

#include <cstdint>
#include <vector>

#include "models/address_generator/address_generator.h"
#include "models/board/board_config.h"
#include "models/comparison_unit/comparison_unit.h"
#include "models/control_registers/control_registers.h"
#include "models/coordinate_memory/coordinate_memory.h"
#include "models/pair_collector/pair_collector.h"

namespace cdvp {

// Wires the blocks of the seed's microarchitecture:
//   address generator -> six 2m-port coordinate memories (1 cycle)
//   -> comparison unit (compare latency) -> pair FIFO -> pair buffer.
// The SystemC shell (CollisionBoard) calls step() on each clock edge while
// running() and forwards host accesses to the register and memory methods.
class BoardCore {
public:
    enum class Phase : uint8_t { Idle, Running, Paused, Done };

    // What travels down the pipeline: the row, the first column and the valid
    // lanes of one address-generator cycle, with the lane hits once compared.
    struct Slot {
        enum Kind : uint8_t { kBubble, kSweep, kEnd } kind = kBubble;
        uint32_t row = 0;
        uint32_t first_column = 0;
        uint32_t valid_lanes = 0;
        uint64_t hits = 0;
    };

    // capacity: boxes the coordinate memories hold (their depth).
    BoardCore(const BoardConfig& config, uint32_t capacity);

    const BoardConfig& config() const { return config_; }
    uint32_t capacity() const { return capacity_; }
    // Block RAM primitives of the six coordinate memories.
    uint32_t block_rams() const;

    // Host side. A read returns false for an unmapped offset.
    bool read_register(uint32_t offset, uint32_t& value) const;
    enum class Write : uint8_t { kDone, kUnmapped, kRefused };
    // A refused write (OBJECT_COUNT during a sweep) also sets ERROR.
    Write write_register(uint32_t offset, uint32_t value);
    // Coordinate memory writes are refused (kRefused, ERROR set) while busy,
    // kUnmapped past capacity.
    Write write_coordinate(Coordinate coordinate, uint32_t index, uint32_t word);
    // Reports an error status (ERROR with this cause, and the interrupt);
    // a sweep under way goes on.
    void raise_error(ControlRegisters::BoardError cause);
    uint32_t read_coordinate(Coordinate coordinate, uint32_t index) const;
    const PairCollector& collector() const { return collector_; }
    const ControlRegisters& registers() const { return regs_; }

    // Clock side.
    Phase phase() const { return phase_; }
    bool running() const { return phase_ == Phase::Running; }
    // One clock edge; every edge counts as a cycle. An edge that finds the
    // pair buffer full pauses the board (and counts as a stall).
    void step();

    // Observation for tracing (cheap accessors; no per-cycle copies).
    const AddressGenerator::Issue& last_issue() const { return last_issue_; }
    const Slot& compare_output() const { return line_[head_]; }
    bool stalled() const { return stalled_; }

private:
    void start();
    void resume();
    void abort();
    Slot issue();
    void finish();

    BoardConfig config_;
    uint32_t capacity_;
    ControlRegisters regs_;
    CoordinateMemories memories_;
    AddressGenerator address_generator_;
    ComparisonUnit comparison_unit_;
    PairCollector collector_;

    Phase phase_ = Phase::Idle;
    // Block RAM stage plus compare stages; head_ is the slot leaving this cycle.
    std::vector<Slot> line_;
    uint32_t head_ = 0;
    bool end_issued_ = false;  // the address generator sent its end marker
    bool end_seen_ = false;    // the end marker reached the collector
    bool stalled_ = false;
    AddressGenerator::Issue last_issue_{};
};

}  // namespace cdvp
