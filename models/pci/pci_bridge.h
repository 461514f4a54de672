// The board's PCI bridge (after the PLX PCI9656 of the ADM-XRC-II): it decodes
// the BAR, forwards accesses to the FPGA over the local bus, and runs a
// bus-master DMA engine between host memory and the FPGA.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "models/pci/bus_timing.h"

namespace cdvp {

// DMA registers, in the BAR above the FPGA's address map.
struct DmaRegisters {
    static constexpr uint64_t kBase = 0x0800'0000;
    static constexpr uint64_t kSize = 0x100;
    enum Offset : uint32_t {
        kHostAddressLo = 0x00,  // rw: host memory (bus) address
        kHostAddressHi = 0x04,
        kLocalAddress = 0x08,   // rw: FPGA address
        kBytes = 0x0C,          // rw: transfer length, a multiple of 4
        kControl = 0x10,        // wo: kStart | kToHost | kInterruptOnDone | kChain
        kStatus = 0x14,         // ro: kBusy, kDone; write kDone to clear it
        kChainLo = 0x18,        // rw: host address of the first descriptor (with kChain)
        kChainHi = 0x1C,
    };
    enum ControlBit : uint32_t {
        kStart = 1u << 0,
        kToHost = 1u << 1,
        kInterruptOnDone = 1u << 2,
        kChain = 1u << 3,  // scatter-gather: walk descriptors in host memory instead of the registers
    };
    enum StatusBit : uint32_t { kBusy = 1u << 0, kDone = 1u << 1 };

    uint64_t host_address = 0;
    uint32_t local_address = 0;
    uint32_t bytes = 0;
    uint64_t chain_address = 0;
    bool chain = false;
    bool to_host = false;
    bool interrupt_on_done = false;
    bool busy = false;
    bool done = false;
};

// A scatter-gather descriptor in host memory (little-endian, 24 bytes);
// next = 0 ends the chain. The whole chain moves in one direction.
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

    // Transfers started (a chain counts once) and segments moved.
    uint64_t dma_transfers() const { return transfers_; }
    uint64_t dma_segments() const { return segments_; }

private:
    void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    unsigned int transport_dbg(tlm::tlm_generic_payload& payload);
    bool access_registers(tlm::tlm_generic_payload& payload);
    void dma_engine();
    void drive_inta();
    // Moves one segment and returns its bus time.
    double transfer_segment(uint64_t host_address, uint32_t local_address, uint32_t bytes, bool to_host);
    void move(tlm::tlm_command command, tlm_utils::simple_initiator_socket<PciBridge>& socket, uint64_t address,
              unsigned char* data, unsigned int length);

    std::shared_ptr<const BusTiming> timing_;
    DmaRegisters dma_;
    sc_core::sc_event dma_start_;
    sc_core::sc_event inta_changed_;
    uint64_t transfers_ = 0;
    uint64_t segments_ = 0;
    std::vector<unsigned char> buffer_;
};

}  // namespace cdvp
