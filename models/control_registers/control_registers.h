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
// Delta stream, write-only: records of kDeltaRecordWords words (box index,
// then its six coordinates in Coordinate order), written in order; the
// board writes each whole record into all six memories (docs/communication.md).
// The offset within the window is ignored: the window is a port, as a FIFO
// is, so a record may be split across bursts.
constexpr uint64_t kDeltaStream = 0x0900'0000;
constexpr uint64_t kDeltaStreamSize = 0x0100'0000;
constexpr uint32_t kDeltaRecordWords = 7;
constexpr uint64_t kDeltaRecordBytes = 4 * kDeltaRecordWords;
// The bus address of coordinate memory c's window.
constexpr uint32_t coordinate_window(uint32_t c) { return static_cast<uint32_t>(kCoordinateBase + c * kWindowSize); }
// The address map limits a board to 4M boxes and 2M buffered pairs.
constexpr uint32_t kMaxObjects = kWindowSize / 4;
constexpr uint32_t kMaxBufferedPairs = kPairBufferSize / 8;
}  // namespace address_map

// The register map: offsets, bits and error causes (BoardCore declares the
// registers themselves). All registers are 32 bits wide; 64-bit counters are
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
        kErrorCause = 0x38,       // ro: why ERROR is set (a BoardError)
        kFormat = 0x3C,           // ro: the comparators' number format: 0 float32, K fixedK (NumberFormat)
        kTileBoxes = 0x40,        // ro: boxes per tile when the boxes sit in SSRAM; 0: block RAM holds them all
        kTileTiming = 0x44,       // ro: tiled boards: bits 15:0 SSRAM load latency, 31:16 cycles per box (kTileTiming*)
        kPairFormat = 0x48,       // rw: how the pair buffer window reads (PairFormat: 0 list, 1 counted, 2 bitmap)
        kPairWords = 0x4C,        // ro: words the pair buffer window holds now, in PAIR_FORMAT
        kDeltaRecords = 0x50,     // ro: delta records written into the memories since the last START
        kBoxBanks = 0x54,         // ro: banks of box memory (1, or 2: double-buffered boxes and pair buffers)
        kHostBank = 0x58,         // ro: the bank the host's coordinate writes and delta records go to
        kPairBank = 0x5C,         // rw: which pair buffer PAIR_COUNT, PAIR_WORDS and the window show (PairBank)
        // The grid board's alone (ID kGridIdValue; docs/grid_board.md), all read-only:
        kGridDims = 0x60,           // board.grid.dims as built: cells a side, 0 for auto
        kGridCellCapacity = 0x64,   // boxes a cell list holds
        kGridMaxSpan = 0x68,        // cells a binned box may cover
        kGridCellSize = 0x6C,       // float32 bits of the fixed cell size; 0: fitted to the frame
        kGridEntryCapacity = 0x70,  // cell entries the memory holds (0xFFFFFFFF: unbounded)
        kGridSweepDims = 0x74,      // the last sweep's cells a side
        kGridLargeBoxes = 0x78,     // the last sweep's boxes swept against every box
        kGridOverflowBoxes = 0x7C,  // of those, boxes that met a full cell or entry memory
        kGridCellEntries = 0x80,    // the last sweep's cell entries
        kGridBusyCells = 0x84,      // the last sweep's cells of two boxes or more
        kGridExcludedBoxes = 0x88,  // the last sweep's boxes with a NaN bound
    };
    // PAIR_BANK's values. With two banks, START keeps the pairs of the sweep
    // before it in the previous pair buffer, to be read during the new sweep.
    enum PairBank : uint32_t { kCurrentPairs = 0, kPreviousPairs = 1 };
    // ABORT stops any sweep and clears every status bit: the board is idle,
    // ready for a new START (a driver's recovery after a fault).
    enum ControlBit : uint32_t { kStart = 1u << 0, kResume = 1u << 1, kAcknowledge = 1u << 2, kAbort = 1u << 3 };
    // kInterrupt: the board holds its interrupt line (from done, overflow or
    // an error until ACKNOWLEDGE): a shared line's handler tells by it
    // whether the board interrupted.
    enum StatusBit : uint32_t {
        kBusy = 1u << 0,
        kDone = 1u << 1,
        kOverflow = 1u << 2,
        kError = 1u << 3,
        kInterrupt = 1u << 4
    };
    // ERROR's causes. An error raises the interrupt like done or overflow.
    enum BoardError : uint32_t {
        kNoError = 0,
        kStartWhileBusy = 1,    // START during a sweep
        kTooManyObjects = 2,    // START with OBJECT_COUNT above the memories' depth
        kResumeNotPaused = 3,   // RESUME without an overflow pause
        kWriteWhileBusy = 4,    // OBJECT_COUNT or a coordinate written during a sweep
        kInjectedError = 5,     // an injected board-error fault (docs/faults.md)
        kDeltaIndex = 6,        // a delta record's box index at or above the capacity
        kDeltaIncomplete = 7,   // START with a delta record partly written
        kBadPairFormat = 8,     // PAIR_FORMAT written with an unknown format
        kPairWindowFull = 9,    // the buffered pairs' encoding outgrows the pair buffer window (a bitmap of too many boxes)
        kBadPairBank = 10,      // PAIR_BANK written with a value other than 0 or 1
    };
    static constexpr uint32_t kIdValue = 0xCD7B'0003;  // "cdvp", register map version 3
    // The grid board: the same map and the grid registers (board variant 1).
    static constexpr uint32_t kGridIdValue = 0xCD7B'1003;
    // TILE_TIMING's fields.
    static constexpr uint32_t kTileTimingLatencyMask = 0xFFFF;
    static constexpr uint32_t kTileTimingCyclesShift = 16;

    static const char* describe(uint32_t cause) {
        switch (cause) {
            case kNoError: return "no error";
            case kStartWhileBusy: return "START while a sweep was under way";
            case kTooManyObjects: return "OBJECT_COUNT above the board's capacity";
            case kResumeNotPaused: return "RESUME without an overflow pause";
            case kWriteWhileBusy: return "a write to OBJECT_COUNT or a coordinate memory during a sweep";
            case kInjectedError: return "the board reported an error (injected board-error)";
            case kDeltaIndex: return "a delta record's box index at or above the capacity";
            case kDeltaIncomplete: return "START with a delta record partly written";
            case kBadPairFormat: return "PAIR_FORMAT written with an unknown format";
            case kPairWindowFull: return "the pairs' encoding outgrew the pair buffer window";
            case kBadPairBank: return "PAIR_BANK written with a value other than 0 or 1";
            default: return "unknown cause";
        }
    }
};

}  // namespace cdvp
