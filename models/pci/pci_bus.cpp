#include "models/pci/pci_bus.h"

namespace cdvp {

using namespace sc_core;

PciBus::PciBus(const sc_module_name& name, std::shared_ptr<const BusTiming> timing)
    : sc_module(name),
      cpu_socket("cpu_socket"),
      board_socket("board_socket"),
      master_socket("master_socket"),
      memory_socket("memory_socket"),
      inta("inta"),
      timing_(std::move(timing)) {
    cpu_socket.register_b_transport(this, &PciBus::cpu_transport);
    cpu_socket.register_transport_dbg(this, &PciBus::cpu_debug);
    master_socket.register_b_transport(this, &PciBus::master_transport);
    SC_METHOD(deliver_interrupt);
    sensitive << inta.pos();
    dont_initialize();
}

void PciBus::cpu_transport(tlm::tlm_generic_payload& payload, sc_time& delay) {
    const double words = (payload.get_data_length() + 3) / 4;
    const double per_word =
        payload.get_command() == tlm::TLM_READ_COMMAND ? timing_->pio_read_ns() : timing_->pio_write_ns();
    // Loosely timed: the access reaches the board when it has crossed the
    // bus, at the initiator's time plus the annotated delay; the targets act
    // at that time, and the initiator decides when to synchronise.
    delay += sc_time(words * per_word, SC_NS);
    Waves& live = waves_.live;
    ++live.pio_accesses;
    live.pio_address = static_cast<uint32_t>(payload.get_address());
    live.pio_write = payload.get_command() == tlm::TLM_WRITE_COMMAND;
    live.pio_bytes = payload.get_data_length();
    waves_.show();
    board_socket->b_transport(payload, delay);
}

void PciBus::master_transport(tlm::tlm_generic_payload& payload, sc_time& delay) {
    waves_.live.master_bytes += payload.get_data_length();
    waves_.show();
    memory_socket->b_transport(payload, delay);
}

void PciBus::add_waves(WaveList& waves) const {
    const std::string p = std::string(name()) + ".";
    waves.group("PCI bus");
    const Waves& shown = waves_.shown();
    waves.add(shown.pio_accesses, p + "pio_accesses", 32, WaveFormat::kDecimal);
    waves.add(shown.pio_address, p + "pio_address", 32, WaveFormat::kHex);
    waves.add(shown.pio_write, p + "pio_write");
    waves.add(shown.pio_bytes, p + "pio_bytes", 32, WaveFormat::kDecimal);
    waves.add(shown.master_bytes, p + "master_bytes", 32, WaveFormat::kDecimal);
}

unsigned int PciBus::cpu_debug(tlm::tlm_generic_payload& payload) { return board_socket->transport_dbg(payload); }

// A lost interrupt never reaches the handler: the driver's timeout finds it.
void PciBus::deliver_interrupt() {
    if (fault_due(faults_, FaultKind::kLostIrq)) return;
    interrupt_.notify(sc_time(timing_->interrupt_ns(), SC_NS));
}

}  // namespace cdvp
