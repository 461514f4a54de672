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
#include <tlm_utils/tlm_quantumkeeper.h>

#include "platform/frame_platform.h"
#include "platform/host_memory.h"
#include "platform/driver/board_driver.h"
#include "platform/driver/host_port.h"

namespace cdvp {

// What the CPU thread does with the next request: one whole frame; with
// frames pipelined (two box banks), start a frame and finish the one before
// it; or finish the frame in flight.
enum class HostRequest : uint8_t { kFrame, kSubmit, kFinish };

// The CPU's own quantum (the global one is shared by every platform in a
// process), with sync points aligned to multiples of it as the global one's.
class HostQuantumKeeper : public tlm_utils::tlm_quantumkeeper {
public:
    explicit HostQuantumKeeper(const sc_core::sc_time& quantum) : quantum_(quantum) {}
    const sc_core::sc_time& quantum() const { return quantum_; }

protected:
    sc_core::sc_time compute_local_quantum() override;

private:
    sc_core::sc_time quantum_;
};

// The CPU thread is the driver's host: it implements the driver's port with
// blocking transport on its initiator socket and SystemC time.
// The CPU thread is loosely timed, as Accellera's lt_td_initiator: accesses
// annotate their delay into a quantum keeper instead of waiting, and the
// thread synchronises when the quantum runs out or before it waits for the
// interrupt.
class HostCpu : public sc_core::sc_module, private HostPort {
public:
    SC_HAS_PROCESS(HostCpu);

    tlm_utils::simple_initiator_socket<HostCpu> socket;  // programmed I/O onto the PCI bus

    // interrupt: when the driver's handler runs; period: the board's clock;
    // quantum: how far the CPU may run ahead of the rest of the simulation
    // (zero: it synchronises at every access, the most accurate).
    HostCpu(const sc_core::sc_module_name& name, HostMemory& memory, const sc_core::sc_event& interrupt,
            const sc_core::sc_time& period, const DriverConfig& config, std::shared_ptr<const BusTiming> bus,
            const sc_core::sc_time& quantum = sc_core::SC_ZERO_TIME);

    // Queues a request for the CPU thread; run the simulation to process it.
    // kSubmit pauses the kernel when the frame has started (the board sweeps
    // on while the caller prepares the next one); the others run until the
    // simulation starves. boxes is not used by kFinish.
    void submit(const std::vector<FloatBox>& boxes, HostRequest request = HostRequest::kFrame);
    bool finished() const { return !pending_; }
    // Whether the last request gave a frame's result (kSubmit's first does not).
    bool completed() const { return completed_; }
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
    void wait(SimTime duration) override;
    void wait_for_interrupt(SimTime timeout) override;
    void wait_for_interrupt_since(SimTime since, SimTime timeout) override;
    std::string transport(tlm::tlm_command command, uint64_t address, void* data, uint32_t length);
    void note_interrupt() { last_interrupt_ = sc_core::sc_time_stamp(); }

    HostMemory& memory_;
    HostQuantumKeeper quantum_keeper_;
    sc_core::sc_time last_interrupt_ = sc_core::sc_max_time();
    // The interrupt wait_for_interrupt_since last returned for without
    // waiting: each is taken once (HostPort's contract, host_port.h).
    sc_core::sc_time taken_interrupt_ = sc_core::sc_max_time();
    const sc_core::sc_event& interrupt_;
    BoardDriver driver_;
    bool opened_ = false;
    const std::vector<FloatBox>* boxes_ = nullptr;
    bool pending_ = false;
    HostRequest request_ = HostRequest::kFrame;
    bool completed_ = false;
    sc_core::sc_event submitted_;
    FrameResult result_;
    FrameFault fault_;
    std::exception_ptr internal_error_;
};

}  // namespace cdvp
