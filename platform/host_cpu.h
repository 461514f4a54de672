// The host PC: a CPU thread that runs the driver, frame by frame.
#pragma once

#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "platform/host_memory.h"
#include "sw/driver/board_driver.h"
#include "sw/driver/host_port.h"

namespace cdvp {

struct FrameResult {
    PairList pairs;  // in the order the board found them
    FramePhases phases;
};

// Why a frame did not complete. Faults travel by value from the CPU thread to
// the caller: an exception rethrown on the main stack after the coroutines
// have run trips AddressSanitizer's stale stack bounds (docs/testing.md).
struct FrameFault {
    enum class Kind : uint8_t { kNone, kDevice, kTimeLimit };
    Kind kind = Kind::kNone;
    std::string message;  // the driver's message, one line
    explicit operator bool() const { return kind != Kind::kNone; }
};

// The CPU thread is the driver's host: it implements the driver's port with
// blocking transport on its initiator socket and SystemC time.
class HostCpu : public sc_core::sc_module, private HostPort {
public:
    SC_HAS_PROCESS(HostCpu);

    tlm_utils::simple_initiator_socket<HostCpu> socket;  // programmed I/O onto the PCI bus

    // interrupt: when the driver's handler runs; period: the board's clock.
    HostCpu(const sc_core::sc_module_name& name, HostMemory& memory, const sc_core::sc_event& interrupt,
            const sc_core::sc_time& period, const DriverConfig& config, std::shared_ptr<const BusTiming> bus);

    // Queues a frame for the CPU thread; run the simulation to process it.
    void submit(const std::vector<FloatBox>& boxes);
    bool finished() const { return !pending_; }
    // The fault that ended the frame (none when it completed).
    const FrameFault& fault() const { return fault_; }
    // Anything else the driver threw (a defect, not a simulated fault).
    std::exception_ptr internal_error() const { return internal_error_; }
    const FrameResult& result() const { return result_; }

private:
    void run();

    // HostPort
    std::string read(uint64_t address, void* data, uint32_t length) override;
    std::string write(uint64_t address, const void* data, uint32_t length) override;
    unsigned char* memory(uint64_t address) override;
    uint64_t memory_size() const override;
    SimTime now() const override;
    SimTime end_of_time() const override;
    void wait(SimTime duration) override;
    void wait_for_interrupt(SimTime timeout) override;
    std::string transport(tlm::tlm_command command, uint64_t address, void* data, uint32_t length);

    HostMemory& memory_;
    const sc_core::sc_event& interrupt_;
    BoardDriver driver_;
    bool opened_ = false;
    const std::vector<FloatBox>* boxes_ = nullptr;
    bool pending_ = false;
    sc_core::sc_event submitted_;
    FrameResult result_;
    FrameFault fault_;
    std::exception_ptr internal_error_;
};

}  // namespace cdvp
