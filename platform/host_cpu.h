// The host PC: a CPU thread that runs the driver, frame by frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "sw/driver/board_driver.h"

namespace cdvp {

struct FrameResult {
    PairList pairs;  // in the order the board found them
    FramePhases phases;
};

class HostCpu : public sc_core::sc_module {
public:
    SC_HAS_PROCESS(HostCpu);

    tlm_utils::simple_initiator_socket<HostCpu> socket;  // programmed I/O onto the PCI bus

    // interrupt: when the driver's handler runs; period: the board's clock.
    HostCpu(const sc_core::sc_module_name& name, HostMemory& memory, const sc_core::sc_event& interrupt,
            const sc_core::sc_time& period, const DriverConfig& config);

    // Queues a frame for the CPU thread; run the simulation to process it.
    void submit(const std::vector<FloatBox>& boxes);
    bool finished() const { return !pending_; }
    const std::string& error() const { return error_; }  // empty when the frame completed
    const FrameResult& result() const { return result_; }

private:
    void run();

    BoardDriver driver_;
    bool opened_ = false;
    const std::vector<FloatBox>* boxes_ = nullptr;
    bool pending_ = false;
    sc_core::sc_event submitted_;
    FrameResult result_;
    std::string error_;
};

}  // namespace cdvp
