// The board's control and status registers and its address map.
#pragma once

#include <cstdint>

namespace cdvp {

// Byte addresses on the board's target socket (one BAR on the host side).
namespace address_map {
constexpr uint64_t kRegisters = 0x0000'0000;
constexpr uint64_t kRegistersSize = 0x1000;
// Coordinate memory c (min_x, min_y, min_z, max_x, max_y, max_z) at
// kCoordinateBase + c * kWindowSize; box i is the 32-bit word at offset 4*i.
constexpr uint64_t kCoordinateBase = 0x0100'0000;
constexpr uint64_t kWindowSize = 0x0100'0000;
// Pair buffer, read-only: pair k is 8 bytes at offset 8*k, first index in the
// low word, second in the high word.
constexpr uint64_t kPairBuffer = 0x0700'0000;
constexpr uint64_t kPairBufferSize = 0x0100'0000;
// The address map limits a board to 4M boxes and 2M buffered pairs.
constexpr uint32_t kMaxObjects = kWindowSize / 4;
constexpr uint32_t kMaxBufferedPairs = kPairBufferSize / 8;
}  // namespace address_map

// Registers as members. All registers are 32 bits wide; 64-bit counters are
// split into _LO/_HI words (read LO first; the board is idle when the host
// reads them, so no latch is needed).
struct ControlRegisters {
    enum Offset : uint32_t {
        kId = 0x00,               // ro: kIdValue
        kControl = 0x04,          // wo: kStart, kResume, kAcknowledge
        kStatus = 0x08,           // ro: kBusy, kDone, kOverflow, kError
        kObjectCount = 0x0C,      // rw: boxes for the next start
        kPairCount = 0x10,        // ro: pairs in the pair buffer now
        kCyclesLo = 0x14,         // ro: board cycles from start to done
        kCyclesHi = 0x18,
        kStallsLo = 0x1C,         // ro: cycles the pipeline could not advance
        kStallsHi = 0x20,
        kTotalPairsLo = 0x24,     // ro: pairs found since start
        kTotalPairsHi = 0x28,
        kParallelism = 0x2C,      // ro: m
        kCapacity = 0x30,         // ro: memory depth in boxes
        kPairBufferDepth = 0x34,  // ro: pair buffer depth in pairs
    };
    enum ControlBit : uint32_t { kStart = 1u << 0, kResume = 1u << 1, kAcknowledge = 1u << 2 };
    enum StatusBit : uint32_t { kBusy = 1u << 0, kDone = 1u << 1, kOverflow = 1u << 2, kError = 1u << 3 };
    static constexpr uint32_t kIdValue = 0xCD7B'0001;  // "cdvp", register map version 1

    uint32_t object_count = 0;
    bool busy = false;      // a sweep is under way (running or paused)
    bool done = false;      // the last sweep finished; every pair is in the buffer
    bool overflow = false;  // paused: the pair buffer is full, drain it and resume
    bool error = false;     // the last command was refused (see board docs)
    bool irq_pending = false;  // set on done or overflow; START, RESUME or ACKNOWLEDGE clear it
    uint64_t cycles = 0;
    uint64_t stalls = 0;

    uint32_t status() const {
        return (busy ? uint32_t{kBusy} : 0u) | (done ? uint32_t{kDone} : 0u) |
               (overflow ? uint32_t{kOverflow} : 0u) | (error ? uint32_t{kError} : 0u);
    }
    // The interrupt line: high from done or overflow until the host
    // acknowledges (so a shared interrupt line can fall between events).
    bool interrupt() const { return irq_pending; }
};

}  // namespace cdvp
