// The board's PCI bridge (after the PLX PCI9656 of the ADM-XRC-II): it decodes
// the BAR, forwards accesses to the FPGA over the local bus, and runs a
// bus-master DMA engine between host memory and the FPGA.
#pragma once

#include <cstdint>
#include <memory>

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
        kControl = 0x10,        // wo: kStart | kToHost | kInterruptOnDone
        kStatus = 0x14,         // ro: kBusy, kDone; write kDone to clear it
    };
    enum ControlBit : uint32_t { kStart = 1u << 0, kToHost = 1u << 1, kInterruptOnDone = 1u << 2 };
    enum StatusBit : uint32_t { kBusy = 1u << 0, kDone = 1u << 1 };

    uint64_t host_address = 0;
    uint32_t local_address = 0;
    uint32_t bytes = 0;
    bool to_host = false;
    bool interrupt_on_done = false;
    bool busy = false;
    bool done = false;
};

class PciBridge : public sc_core::sc_module {
public:
    SC_HAS_PROCESS(PciBridge);

    tlm_utils::simple_target_socket<PciBridge> pci_target;     // the BAR, from the PCI bus
    tlm_utils::simple_initiator_socket<PciBridge> pci_master;  // DMA into host memory
    tlm_utils::simple_initiator_socket<PciBridge> local_bus;   // to the FPGA
    sc_core::sc_in<bool> fpga_irq;                             // the FPGA's interrupt (LINTi#)
    sc_core::sc_out<bool> inta;                                // INTA# to the host

    PciBridge(const sc_core::sc_module_name& name, std::shared_ptr<const BusTiming> timing);

    uint64_t dma_transfers() const { return transfers_; }

private:
    void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    unsigned int transport_dbg(tlm::tlm_generic_payload& payload);
    bool access_registers(tlm::tlm_generic_payload& payload);
    void dma_engine();
    void drive_inta();
    void move(tlm::tlm_command command, tlm_utils::simple_initiator_socket<PciBridge>& socket, uint64_t address,
              unsigned char* data, unsigned int length);

    std::shared_ptr<const BusTiming> timing_;
    DmaRegisters dma_;
    sc_core::sc_event dma_start_;
    sc_core::sc_event inta_changed_;
    uint64_t transfers_ = 0;
};

}  // namespace cdvp
