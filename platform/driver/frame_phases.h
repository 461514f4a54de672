// What a frame of the driver's sequence gives (its phases) and how it fails:
// the same at every level, the platform's driver and the analytic one.
#pragma once

#include <cstdint>
#include <stdexcept>

namespace cdvp {

// The simulated system faulted (a DMA or bus fault, a board error status, a
// driver timeout): the input was fine. The frame produced no pairs.
class DeviceFault : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A wait's deadline would pass kSimulatedTimeLimit (platform/driver/frame_time.h):
// refused before the wait starts. cdvp run's estimate before any work holds
// a whole run to the same limit, so a run it lets through never meets this.
class SimulatedTimeLimit : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Where a frame's simulated time went; the phases add up to total_ns.
struct FramePhases {
    double upload_ns = 0;    // staging boxes on the board (one DMA chain or PIO, with set-up and completion)
    double start_ns = 0;     // writing the object count and START
    double compute_ns = 0;   // the board's clock running (cycles x period)
    double irq_ns = 0;       // from the board's interrupt to the driver noticing (interrupt or polling)
    double readback_ns = 0;  // status reads, pair transfers, RESUME after overflows
    double driver_ns = 0;    // host CPU work: packing boxes, unpacking pairs, driver calls
    double total_ns = 0;
    uint64_t compute_cycles = 0;
    uint64_t stall_cycles = 0;
    // What moved over the bus: the boxes uploaded (all of them, or the
    // changed ones of a delta upload), their bytes, and the pair words' bytes.
    uint32_t boxes_sent = 0;
    uint64_t upload_bytes = 0;
    uint64_t readback_bytes = 0;
    uint32_t overflow_pauses = 0;
    uint32_t timeouts_recovered = 0;  // waits whose interrupt never came, finished by polling STATUS
    // On a board with two box banks (frames pipelined): the frame's sweep
    // time hidden behind the host's work on the frames beside it (not in
    // total_ns, which is the host's time on this frame), and the frame's
    // latency, from the start of its upload to its last pair in host memory.
    // One frame at a time: overlap 0 and latency = total.
    double overlap_ns = 0;
    double latency_ns = 0;
};

}  // namespace cdvp
