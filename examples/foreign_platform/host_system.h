// A host system of the example's own: RAM, an address-decoding interconnect
// and a CPU whose software reaches the board through cdvp's HostPort. Nothing
// here comes from cdvp's platform: only the HostPort interface it implements.
#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_initiator_socket.h>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "platform/driver/host_port.h"

namespace example {

// The system address map. DMA addresses are host-physical, and the driver
// hands the bridge offsets into HostPort::memory(): so RAM sits at 0.
constexpr uint64_t kRamBase = 0x0;
constexpr uint64_t kBoardBarBase = 0x8000'0000;
constexpr uint64_t kBoardBarSize = 0x1000'0000;  // the board's map and the bridge's DMA registers

class HostRam : public sc_core::sc_module {
public:
    tlm_utils::simple_target_socket<HostRam> socket;

    HostRam(const sc_core::sc_module_name& name, uint64_t bytes);
    unsigned char* data(uint64_t offset) { return bytes_.data() + offset; }
    uint64_t size() const { return bytes_.size(); }

private:
    void b_transport(tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    std::vector<unsigned char> bytes_;
};

// Any initiator to any target by address: each route a window of the map,
// its addresses made relative to the window's base, with a latency per
// 32-bit word (the PCI cost of programmed I/O to the board).
class Interconnect : public sc_core::sc_module {
public:
    tlm_utils::multi_passthrough_target_socket<Interconnect> initiators;  // CPU, the bridge's DMA master
    tlm_utils::multi_passthrough_initiator_socket<Interconnect> targets;  // RAM, the board's BAR

    explicit Interconnect(const sc_core::sc_module_name& name);
    // The next target bound to `targets` answers [base, base + size).
    void add_route(uint64_t base, uint64_t size, double read_ns_per_word = 0, double write_ns_per_word = 0);

private:
    struct Route {
        uint64_t base, size;
        double read_ns_per_word, write_ns_per_word;
    };
    void b_transport(int initiator, tlm::tlm_generic_payload& payload, sc_core::sc_time& delay);
    std::vector<Route> routes_;
};

// A loosely-timed CPU running one program, the host software, on its thread.
// It implements cdvp's HostPort with blocking transport through its socket
// and a quantum keeper, and takes the interrupt line as a level-triggered
// pin whose handler runs `interrupt_latency` after the line rises.
class HostProcessor : public sc_core::sc_module, public cdvp::HostPort {
public:
    SC_HAS_PROCESS(HostProcessor);
    using Program = std::function<void(cdvp::HostPort&)>;

    tlm_utils::simple_initiator_socket<HostProcessor> socket;
    sc_core::sc_in<bool> irq;

    HostProcessor(const sc_core::sc_module_name& name, HostRam& ram, const sc_core::sc_time& interrupt_latency,
                  Program program);
    // What the program threw, if anything (rethrown by sc_main, off the thread).
    std::exception_ptr failure() const { return failure_; }

    std::string read(uint64_t address, void* data, uint32_t length) override;
    std::string write(uint64_t address, const void* data, uint32_t length) override;
    unsigned char* memory(uint64_t address) override { return ram_.data(address); }
    uint64_t memory_size() const override { return ram_.size(); }
    cdvp::SimTime now() const override;
    void wait(cdvp::SimTime duration) override;
    void wait_for_interrupt(cdvp::SimTime timeout) override;

private:
    void run();
    void raise_handler() { handler_.notify(interrupt_latency_); }
    void note_handler() { last_handler_ = sc_core::sc_time_stamp(); }
    // address: an offset in the board's BAR.
    std::string transport(tlm::tlm_command command, uint64_t address, void* data, uint32_t length);

    HostRam& ram_;
    sc_core::sc_time interrupt_latency_;
    Program program_;
    tlm_utils::tlm_quantumkeeper keeper_;
    sc_core::sc_event handler_;
    sc_core::sc_time last_handler_ = sc_core::sc_max_time();
    std::exception_ptr failure_;
};

}  // namespace example
