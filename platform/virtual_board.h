// The virtual platform: the collision board and a host, wired and traced.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <systemc>

#include "models/board/collision_board.h"
#include "platform/simple_host.h"

namespace cdvp {

// Elaborate once, then run any number of frames: each run_frame() hands the
// boxes to the host thread and simulates until the board is idle again (the
// board's clock does not tick between frames, so the kernel simply starves).
class VirtualBoard : public sc_core::sc_module {
public:
    // capacity: the most boxes any frame will hold (sizes the coordinate memories).
    // vcd_base: when not empty, waveforms go to vcd_base + ".vcd".
    VirtualBoard(const sc_core::sc_module_name& name, const BoardConfig& config, uint32_t capacity,
                 const std::string& vcd_base = "");
    ~VirtualBoard() override;

    // Runs one frame; throws std::runtime_error if the host could not complete it.
    const FrameResult& run_frame(const std::vector<FloatBox>& boxes);
    // Flushes and closes the waveform file (also done by the destructor).
    void close_trace();

    const CollisionBoard& board() const { return board_; }

private:
    CollisionBoard board_;
    SimpleHost host_;
    sc_core::sc_signal<bool> irq_;
    sc_core::sc_trace_file* trace_ = nullptr;
};

}  // namespace cdvp
