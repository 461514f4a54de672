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
#include "models/common/wave_list.h"
#include "models/pci/dma_registers.h"
#include "models/pci/bus_timing.h"

namespace cdvp {

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

    // Adds the DMA engine's waveforms (state, busy, direction, bytes,
    // descriptors, error) to a trace file, before the first sc_start.
    void add_waves(WaveList& waves) const;
    // Whether the frames that follow are traced (a --vcd-frames window):
    // outside it the DMA engine's waveforms hold.
    void set_tracing(bool on) { waves_.set_open(on); }
    // The DMA engine's states as the waveforms name them: idle, moving to
    // the board, moving to the host, or idle after a failed transfer.
    static const StateNames kDmaStates;

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
    void show_waves();

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
    // Waveform values: the transfer under way, kept current whether traced or not.
    struct Waves {
        bool busy = false, to_host = false, error = false;
        uint32_t bytes = 0;        // bytes of the transfer (every segment of a chain)
        uint32_t descriptors = 0;  // descriptors fetched (0 in register mode)
        uint32_t state = 0;        // kDmaStates, from the three bits above
    };
    GatedWaves<Waves> waves_;
};

}  // namespace cdvp
