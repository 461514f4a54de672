// Virtex-II block RAM primitive (18 Kbit) in one of its aspect ratios: 512x36
// for 32-bit words, 1Kx18 or 2Kx9 for narrower ones (NumberFormat).
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

    // words: the aspect's depth, a power of two (512, 1024 or 2048).
    explicit BlockRam(uint32_t words = kWords) : words_(words, 0), last_(words - 1) {}

    uint32_t words() const { return static_cast<uint32_t>(words_.size()); }

    // Synchronous write through a port (used by the host side while the board is idle).
    void write(uint32_t address, uint32_t word) { words_[address & last_] = word; }

    // A clock edge on one port with its enable high: registers the addressed word.
    void clock_read(int port, uint32_t address) { out_[port] = words_[address & last_]; }

    // The port's output register (valid from the edge after clock_read).
    uint32_t output(int port) const { return out_[port]; }

    // Direct view for the cascade that owns the primitive.
    uint32_t peek(uint32_t address) const { return words_[address & last_]; }

private:
    std::vector<uint32_t> words_;
    uint32_t last_;  // address mask
    std::array<uint32_t, kPorts> out_{};
};

// A memory of arbitrary depth cascaded from ceil(depth / W) primitives of W
// words each: the upper address bits select the primitive, the lower ones the
// word. Both ports
// read any depth with the primitive's one-cycle latency (the output multiplexer
// is assumed registered with the primitive's output).
class CascadedBlockRam {
public:
    // words_per_primitive: the primitives' aspect depth (NumberFormat::block_ram_layout).
    explicit CascadedBlockRam(uint32_t depth, uint32_t words_per_primitive = BlockRam::kWords);

    uint32_t depth() const { return depth_; }
    uint32_t primitives() const { return static_cast<uint32_t>(bank_.size()); }

    void write(uint32_t address, uint32_t word);
    void clock_read(int port, uint32_t address) { out_[port] = bank_[address >> shift_].peek(address); }
    uint32_t output(int port) const { return out_[port]; }
    uint32_t peek(uint32_t address) const { return bank_[address >> shift_].peek(address); }

    static uint32_t primitives_for(uint32_t depth, uint32_t words_per_primitive = BlockRam::kWords) {
        return static_cast<uint32_t>((uint64_t{depth} + words_per_primitive - 1) / words_per_primitive);
    }

private:
    uint32_t depth_;
    uint32_t shift_;  // log2 of the words per primitive
    std::vector<BlockRam> bank_;
    std::array<uint32_t, BlockRam::kPorts> out_{};
};

}  // namespace cdvp
