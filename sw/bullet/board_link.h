// How a BoardBroadphase reaches a board: one frame of float boxes in, the
// board's pairs and phase times out. The virtual board is one link; tests may
// use a plain C++ one to check the broad phase's bookkeeping without SystemC.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "platform/virtual_board.h"

namespace cdvp {

// The simulated system faulted on a frame (a bus or board fault the driver
// could not recover from); the frame's pairs are unknown.
class BoardFrameFault : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class BoardLink {
public:
    virtual ~BoardLink() = default;
    // The most boxes one frame may hold.
    virtual uint32_t capacity() const = 0;
    // Runs one frame; the pairs index 'boxes' (first < second). Throws
    // BoardFrameFault when the simulated system faulted.
    virtual const FrameResult& run(const std::vector<FloatBox>& boxes) = 0;
};

// The virtual board, elaborated on the first frame. SystemC elaborates a
// design once per process, so a process holds at most one: constructing a
// second LazyVirtualBoard is allowed, running it is refused (std::logic_error).
// Share one link between broad phases instead; its capacity is fixed here.
class LazyVirtualBoard : public BoardLink {
public:
    LazyVirtualBoard(PlatformConfig config, uint32_t capacity);
    ~LazyVirtualBoard() override;

    uint32_t capacity() const override { return capacity_; }
    const FrameResult& run(const std::vector<FloatBox>& boxes) override;

    // Null until the first frame.
    const VirtualBoard* board() const { return board_.get(); }
    const PlatformConfig& config() const { return config_; }

private:
    PlatformConfig config_;
    uint32_t capacity_;
    uint64_t frames_ = 0;
    std::unique_ptr<VirtualBoard> board_;
};

}  // namespace cdvp
