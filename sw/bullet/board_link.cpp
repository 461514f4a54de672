#include "sw/bullet/board_link.h"

#include <utility>

namespace cdvp {

namespace {

// Set by the first LazyVirtualBoard that elaborates; SystemC cannot elaborate again.
bool g_elaborated = false;

void check_capacity(const std::vector<FloatBox>& boxes, uint32_t capacity) {
    if (boxes.size() > capacity) {
        throw std::length_error("a frame of " + std::to_string(boxes.size()) + " proxies exceeds the board's capacity of " +
                                std::to_string(capacity) + " boxes");
    }
}

}  // namespace

const FrameResult& PlatformLink::run(const std::vector<FloatBox>& boxes) {
    check_capacity(boxes, capacity_);
    fault_ = FrameFault{};
    result_ = board_.try_run_frame(boxes, frames_++, fault_);
    if (result_ == nullptr) throw BoardFrameFault(fault_.message);
    return *result_;
}

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
        link_ = std::make_unique<PlatformLink>(*board_, capacity_);
    }
    return link_->run(boxes);
}

const FrameResult& HostPairsLink::run(const std::vector<FloatBox>& boxes) {
    check_capacity(boxes, capacity_);
    result_.pairs.clear();
    finder_.find(static_cast<uint32_t>(boxes.size()), float32_words(boxes, words_), result_.pairs);
    return result_;
}

}  // namespace cdvp
