// Host RAM as a TLM-2.0 target: where the driver stages boxes and the
// bridge's DMA engine writes pairs.
#pragma once

#include <cstdint>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>

namespace cdvp {

class HostMemory : public sc_core::sc_module {
public:
    tlm_utils::simple_target_socket<HostMemory> socket;

    HostMemory(const sc_core::sc_module_name& name, uint64_t bytes);

    // The CPU's own view of its memory (no bus involved).
    unsigned char* data(uint64_t address) { return bytes_.data() + address; }
    uint64_t size() const { return bytes_.size(); }

private:
    void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);

    std::vector<unsigned char> bytes_;
};

}  // namespace cdvp
