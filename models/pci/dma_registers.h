// The PCI bridge's DMA engine as the host sees it: its registers, its
// descriptor format and its fault causes. Plain C++: the driver includes this,
// never the bridge's SystemC model.
#pragma once

#include <cstdint>

namespace cdvp {

// Why a DMA stopped (the DMA error-cause register). Like the PCI9656's abort
// status bits, each names the side and the kind of failure.
enum class DmaFault : uint32_t {
    kNone = 0,
    kBadLength = 1,        // zero, not a multiple of 4, or above kMaxSegmentBytes
    kMisaligned = 2,       // a host or local address not 4-aligned, or a descriptor not 8-aligned
    kMasterAbort = 3,      // no host memory claimed the host address
    kTargetAbort = 4,      // the board aborted the local access (outside its map, or beyond its pairs)
    kBoardRefused = 5,     // the board refused the local access (a sweep runs, or a read-only area)
    kDescriptorFault = 6,  // no host memory claimed a descriptor's address
    kChainLoop = 7,        // the chain came back to a descriptor it had run
    kChainTooLong = 8,     // more than kMaxDescriptors descriptors
    kStartWhileBusy = 9,   // START while a transfer was under way (that transfer goes on)
};
// "master abort (host memory did not claim the address)" and so on.
const char* describe(DmaFault fault);

// DMA registers, in the BAR above the FPGA's address map.
struct DmaRegisters {
    static constexpr uint64_t kBase = 0x0800'0000;
    static constexpr uint64_t kSize = 0x100;
    enum Offset : uint32_t {
        kHostAddressLo = 0x00,  // rw: host memory (bus) address
        kHostAddressHi = 0x04,
        kLocalAddress = 0x08,   // rw: FPGA address
        kBytes = 0x0C,          // rw: transfer length, a multiple of 4
        kControl = 0x10,        // wo: kStart | kToHost | kInterruptOnDone | kChain, or kAbort
        kStatus = 0x14,         // ro: kBusy, kDone, kError; write kDone / kError to clear them
        kChainLo = 0x18,        // rw: host address of the first descriptor (with kChain)
        kChainHi = 0x1C,
        kErrorCause = 0x20,     // ro: a DmaFault, valid while kError is set
        kErrorAddressLo = 0x24, // ro: the host or local address that faulted
        kErrorAddressHi = 0x28,
    };
    enum ControlBit : uint32_t {
        kStart = 1u << 0,
        kToHost = 1u << 1,
        kInterruptOnDone = 1u << 2,  // interrupt when the transfer ends, done or faulted
        kChain = 1u << 3,  // scatter-gather: walk descriptors in host memory instead of the registers
        kAbort = 1u << 4,  // stop the transfer under way (a hung one too) and clear the status
    };
    enum StatusBit : uint32_t { kBusy = 1u << 0, kDone = 1u << 1, kError = 1u << 2 };
    // The largest segment: one window of the board's map (4M boxes).
    static constexpr uint32_t kMaxSegmentBytes = 1u << 24;
    // A longer chain is refused: a loop the revisit check misses cannot hang the host.
    static constexpr uint32_t kMaxDescriptors = 1024;

    uint64_t host_address = 0;
    uint32_t local_address = 0;
    uint32_t bytes = 0;
    uint64_t chain_address = 0;
    bool chain = false;
    bool to_host = false;
    bool interrupt_on_done = false;
    bool busy = false;
    bool done = false;
    bool error = false;
    DmaFault cause = DmaFault::kNone;
    uint64_t fault_address = 0;

    uint32_t status() const {
        return (busy ? uint32_t{kBusy} : 0u) | (done ? uint32_t{kDone} : 0u) | (error ? uint32_t{kError} : 0u);
    }
};

// A scatter-gather descriptor in host memory (little-endian, 24 bytes, at an
// 8-aligned address); next = 0 ends the chain. The whole chain moves in one direction.
struct DmaDescriptor {
    uint64_t host_address;
    uint64_t next;
    uint32_t local_address;
    uint32_t bytes;
};
static_assert(sizeof(DmaDescriptor) == 24, "descriptor layout");

}  // namespace cdvp
