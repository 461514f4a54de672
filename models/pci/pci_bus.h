// The host's PCI (or PCIe) link as a loosely timed TLM-2.0 interconnect.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "models/common/fault_plan.h"
#include "models/common/wave_list.h"
#include "models/pci/bus_timing.h"

namespace cdvp {

// Programmed I/O from the CPU goes to the board's BAR with the bus's read or
// write cost annotated per 32-bit word (the CPU does single, uncached
// accesses). The bridge's bus-master accesses reach host memory untimed here:
// the bridge accounts a DMA transfer as a whole. The board's interrupt pin
// reaches the driver's handler an interrupt latency after it rises.
class PciBus : public sc_core::sc_module {
public:
    SC_HAS_PROCESS(PciBus);

    tlm_utils::simple_target_socket<PciBus> cpu_socket;        // host CPU, programmed I/O
    tlm_utils::simple_initiator_socket<PciBus> board_socket;   // the board's BAR (its bridge)
    tlm_utils::simple_target_socket<PciBus> master_socket;     // the bridge as bus master
    tlm_utils::simple_initiator_socket<PciBus> memory_socket;  // host memory
    sc_core::sc_in<bool> inta;                                 // the board's interrupt pin

    PciBus(const sc_core::sc_module_name& name, std::shared_ptr<const BusTiming> timing);

    const BusTiming& timing() const { return *timing_; }
    // Faults to inject (lost-irq); null for none. Not owned.
    void set_fault_plan(FaultPlan* plan) { faults_ = plan; }
    // Notified when the driver's interrupt handler runs.
    const sc_core::sc_event& interrupt_event() const { return interrupt_; }
    // Adds the bus's waveforms to a trace file, before the first sc_start:
    // the CPU's programmed I/O (accesses so far, the last one's address,
    // direction and bytes) and the bytes the bridge moved as bus master, so
    // that PIO transfers and DMA show beside the board's compute.
    void add_waves(WaveList& waves) const;
    // Whether the frames that follow are traced (a --vcd-frames window):
    // outside it the bus's waveforms hold.
    void set_tracing(bool on) { waves_.set_open(on); }

private:
    void cpu_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    void master_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    unsigned int cpu_debug(tlm::tlm_generic_payload& payload);
    void deliver_interrupt();

    std::shared_ptr<const BusTiming> timing_;
    sc_core::sc_event interrupt_;
    FaultPlan* faults_ = nullptr;
    // Waveform values, kept current whether traced or not.
    struct Waves {
        uint32_t pio_accesses = 0;
        uint32_t pio_address = 0;
        bool pio_write = false;
        uint32_t pio_bytes = 0;
        uint32_t master_bytes = 0;
    };
    GatedWaves<Waves> waves_;
};

}  // namespace cdvp
