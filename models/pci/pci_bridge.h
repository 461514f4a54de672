// The board's PCI bridge (after the PLX PCI9656 of the ADM-XRC-II): it decodes
// the BAR, forwards accesses to the FPGA over the local bus, and runs a
// bus-master DMA engine between host memory and the FPGA.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "models/common/fault_plan.h"
#include "models/common/register_bank.h"
#include "models/pci/bus_timing.h"

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

class PciBridge : public sc_core::sc_module {
public:
    SC_HAS_PROCESS(PciBridge);

    tlm_utils::simple_target_socket<PciBridge> pci_target;     // the BAR, from the PCI bus
    tlm_utils::simple_initiator_socket<PciBridge> pci_master;  // DMA into host memory
    tlm_utils::simple_initiator_socket<PciBridge> local_bus;   // to the FPGA
    sc_core::sc_in<bool> fpga_irq;                             // the FPGA's interrupt (LINTi#)
    sc_core::sc_out<bool> inta;                                // INTA# to the host

    PciBridge(const sc_core::sc_module_name& name, std::shared_ptr<const BusTiming> timing);

    // Faults to inject (aborts, retry, disconnect, hang); null for none. Not owned.
    void set_fault_plan(FaultPlan* plan) { faults_ = plan; }

    // Transfers started (a chain counts once) and segments moved.
    uint64_t dma_transfers() const { return transfers_; }
    uint64_t dma_segments() const { return segments_; }
    // Bus transactions repeated after a retry or a disconnect.
    uint64_t repeated_transactions() const { return repeated_; }
    const DmaRegisters& dma_registers() const { return dma_; }

    // Bytes moved per local-bus or host transaction: the engine's only buffer.
    static constexpr uint32_t kBurstBytes = 4096;

private:
    struct Fault {
        DmaFault cause = DmaFault::kNone;
        uint64_t address = 0;
        explicit operator bool() const { return cause != DmaFault::kNone; }
    };

    void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    unsigned int transport_dbg(tlm::tlm_generic_payload& payload);
    tlm::tlm_response_status access_registers(tlm::tlm_generic_payload& payload);
    void declare_registers();
    void clear_error();
    void write_control(uint32_t value);
    void dma_engine();
    Fault run_transfer(double& ns);
    void drive_inta();
    // Checks a segment before anything moves.
    static Fault check_segment(uint64_t host_address, uint32_t local_address, uint32_t bytes);
    // Moves one checked segment in bursts; adds its bus time to ns, up to the fault if one occurs.
    Fault transfer_segment(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host, double& ns);
    // The bus time of one transaction of bytes, with injected retries and disconnects.
    double transaction_ns(uint32_t bytes, Direction direction);
    Fault move_burst(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host);
    Fault fetch_descriptor(uint64_t address, DmaDescriptor& descriptor);
    void finish(const Fault& fault);

    std::shared_ptr<const BusTiming> timing_;
    FaultPlan* faults_ = nullptr;
    DmaRegisters dma_;
    RegisterBank registers_;
    sc_core::sc_event dma_start_;
    sc_core::sc_event abort_;
    sc_core::sc_event inta_changed_;
    bool abort_requested_ = false;
    uint64_t transfers_ = 0;
    uint64_t segments_ = 0;
    uint64_t repeated_ = 0;
    std::vector<unsigned char> buffer_;
};

}  // namespace cdvp
