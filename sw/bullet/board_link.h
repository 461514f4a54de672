// How a BoardBroadphase reaches a board: one frame of float boxes in, the
// board's pairs and phase times out. The virtual board is one link; tests may
// use a plain C++ one to check the broad phase's bookkeeping without SystemC.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/fast_engine/pair_finder.h"
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

// A virtual board the caller elaborated (with waveforms, say, as `cdvp
// bullet --vcd` does), frames numbered from 0 in the order they run. A frame
// beyond the capacity the board was built for is refused (std::length_error).
class PlatformLink : public BoardLink {
public:
    PlatformLink(FramePlatform& board, uint32_t capacity) : board_(board), capacity_(capacity) {}

    uint32_t capacity() const override { return capacity_; }
    const FrameResult& run(const std::vector<FloatBox>& boxes) override;
    // Why the frame that threw BoardFrameFault failed: a device fault, the
    // simulated-time limit or the pair budget, each its own exit.
    const FrameFault& last_fault() const { return fault_; }
    // The last frame's pairs and phases (null before the first).
    const FrameResult* last_result() const { return result_; }

private:
    FramePlatform& board_;
    uint32_t capacity_;
    uint64_t frames_ = 0;
    FrameFault fault_;
    const FrameResult* result_ = nullptr;
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
    std::unique_ptr<VirtualBoard> board_;
    std::unique_ptr<PlatformLink> link_;
};

// The board's float32 comparisons, done on the host by the fast engine's
// search, untimed: a float32 board's pairs of every frame (closed intervals,
// the lanes' semantics) and none of its time or SystemC. A world on it moves
// as a world on the board does, at the cost of a sort and sweep a frame.
class HostPairsLink : public BoardLink {
public:
    explicit HostPairsLink(uint32_t capacity) : capacity_(capacity) {}

    uint32_t capacity() const override { return capacity_; }
    const FrameResult& run(const std::vector<FloatBox>& boxes) override;

private:
    uint32_t capacity_;
    PairFinder finder_;
    std::vector<uint32_t> words_[kCoordinates];
    FrameResult result_;
};

}  // namespace cdvp
