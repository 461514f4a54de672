#include "platform/virtual_board.h"

#include <stdexcept>

namespace cdvp {

using namespace sc_core;

VirtualBoard::VirtualBoard(const sc_module_name& name, const BoardConfig& config, uint32_t capacity,
                           const std::string& vcd_base)
    : sc_module(name), board_("board", config, capacity), host_("host"), irq_("irq") {
    host_.socket.bind(board_.socket);
    board_.irq.bind(irq_);
    host_.irq.bind(irq_);
    if (!vcd_base.empty()) {
        trace_ = sc_create_vcd_trace_file(vcd_base.c_str());
        if (trace_ == nullptr) throw std::runtime_error(vcd_base + ".vcd: cannot create waveform file");
        trace_->set_time_unit(1, SC_PS);
        board_.trace(trace_);
        sc_trace(trace_, irq_, std::string(this->name()) + ".irq");
    }
}

VirtualBoard::~VirtualBoard() { close_trace(); }

void VirtualBoard::close_trace() {
    if (trace_ != nullptr) {
        sc_close_vcd_trace_file(trace_);
        trace_ = nullptr;
    }
}

const FrameResult& VirtualBoard::run_frame(const std::vector<FloatBox>& boxes) {
    if (boxes.size() > board_.core().capacity()) {
        throw std::invalid_argument("frame of " + std::to_string(boxes.size()) +
                                    " boxes exceeds the board's capacity of " +
                                    std::to_string(board_.core().capacity()));
    }
    host_.submit(boxes);
    sc_start();  // returns when no activity is left: the frame is complete
    if (!host_.finished()) throw std::runtime_error("the simulation stopped before the frame completed");
    if (!host_.error().empty()) throw std::runtime_error(host_.error());
    return host_.result();
}

}  // namespace cdvp
