// A minimal host: loads a frame's boxes through the board's socket, starts the
// sweep, and drains the pair buffer on every interrupt until done.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "models/common/aabb.h"

namespace cdvp {

// What one frame produced, as read back from the board's registers.
struct FrameResult {
    PairList pairs;                // in the order the board found them
    uint64_t compute_cycles = 0;   // start to done, from the cycle counter
    uint64_t stall_cycles = 0;
    uint32_t overflow_pauses = 0;  // times the pair buffer filled and was drained
    sc_core::sc_time started;      // simulated time of the START write
    sc_core::sc_time finished;     // simulated time the last pair was read
};

class SimpleHost : public sc_core::sc_module {
public:
    SC_HAS_PROCESS(SimpleHost);

    tlm_utils::simple_initiator_socket<SimpleHost> socket;
    sc_core::sc_in<bool> irq;

    explicit SimpleHost(const sc_core::sc_module_name& name);

    // Queues a frame for the host thread; run the simulation to process it.
    void submit(const std::vector<FloatBox>& boxes);
    bool finished() const { return !pending_; }
    // Empty when the frame completed; otherwise what went wrong.
    const std::string& error() const { return error_; }
    const FrameResult& result() const { return result_; }

private:
    void run();
    void process_frame();
    void transfer(tlm::tlm_command command, uint64_t address, void* data, unsigned int length);
    void write_word(uint64_t address, uint32_t value) { transfer(tlm::TLM_WRITE_COMMAND, address, &value, 4); }
    uint32_t read_word(uint64_t address);
    uint64_t read_counter(uint32_t low_offset);
    void read_pair_buffer();

    const std::vector<FloatBox>* boxes_ = nullptr;
    bool pending_ = false;
    sc_core::sc_event submitted_;
    FrameResult result_;
    std::string error_;
};

}  // namespace cdvp
