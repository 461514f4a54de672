// Virtex-II block RAM primitive in its 512x36 shape, used as 512 words of 32 bits.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace cdvp {

// True dual-port, synchronous RAM: each port takes one address per clock edge
// and presents the word on its output register after that edge (one cycle of
// read latency). A port with its enable low keeps its output register, which is
// how a stalled pipeline holds its data.
class BlockRam {
public:
    static constexpr uint32_t kWords = 512;  // 512x36 shape, 32 data bits used
    static constexpr uint32_t kReadLatencyCycles = 1;
    static constexpr int kPorts = 2;

    // Synchronous write through a port (used by the host side while the board is idle).
    void write(uint32_t address, uint32_t word) { words_[address % kWords] = word; }

    // A clock edge on one port with its enable high: registers the addressed word.
    void clock_read(int port, uint32_t address) { out_[port] = words_[address % kWords]; }

    // The port's output register (valid from the edge after clock_read).
    uint32_t output(int port) const { return out_[port]; }

    // Direct view for the cascade that owns the primitive.
    uint32_t peek(uint32_t address) const { return words_[address % kWords]; }

private:
    std::array<uint32_t, kWords> words_{};
    std::array<uint32_t, kPorts> out_{};
};

// A memory of arbitrary depth cascaded from ceil(depth / 512) primitives: the
// upper address bits select the primitive, the lower nine the word. Both ports
// read any depth with the primitive's one-cycle latency (the output multiplexer
// is assumed registered with the primitive's output).
class CascadedBlockRam {
public:
    explicit CascadedBlockRam(uint32_t depth);

    uint32_t depth() const { return depth_; }
    uint32_t primitives() const { return static_cast<uint32_t>(bank_.size()); }

    void write(uint32_t address, uint32_t word);
    void clock_read(int port, uint32_t address) {
        out_[port] = bank_[address / BlockRam::kWords].peek(address);
    }
    uint32_t output(int port) const { return out_[port]; }
    uint32_t peek(uint32_t address) const { return bank_[address / BlockRam::kWords].peek(address); }

    static uint32_t primitives_for(uint32_t depth) {
        return (depth + BlockRam::kWords - 1) / BlockRam::kWords;
    }

private:
    uint32_t depth_;
    std::vector<BlockRam> bank_;
    std::array<uint32_t, BlockRam::kPorts> out_{};
};

}  // namespace cdvp
