#include "sw/bullet/board_link.h"

#include <utility>

namespace cdvp {

namespace {
// Set by the first LazyVirtualBoard that elaborates; SystemC cannot elaborate again.
bool g_elaborated = false;
}  // namespace

LazyVirtualBoard::LazyVirtualBoard(PlatformConfig config, uint32_t capacity)
    : config_(std::move(config)), capacity_(capacity) {}

LazyVirtualBoard::~LazyVirtualBoard() = default;

const FrameResult& LazyVirtualBoard::run(const std::vector<FloatBox>& boxes) {
    if (!board_) {
        if (g_elaborated) {
            throw std::logic_error(
                "a process elaborates one virtual board: share the first LazyVirtualBoard instead of creating another");
        }
        g_elaborated = true;
        board_ = std::make_unique<VirtualBoard>("bullet_board", config_, capacity_);
    }
    if (boxes.size() > capacity_) {
        throw std::length_error("a frame of " + std::to_string(boxes.size()) + " proxies exceeds the board's capacity of " +
                                std::to_string(capacity_) + " boxes");
    }
    FrameFault fault;
    const FrameResult* result = board_->try_run_frame(boxes, frames_++, fault);
    if (result == nullptr) throw BoardFrameFault(fault.message);
    return *result;
}

}  // namespace cdvp
