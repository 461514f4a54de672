// The seed's "2m-port" memory: m dual-port block RAMs holding the same data.
#pragma once

#include <cstdint>
#include <vector>

#include "models/block_ram/block_ram.h"

namespace cdvp {

// One coordinate (e.g. min_x) of every box, replicated in m cascaded block RAMs
// so that 2m addresses can be read each cycle: port p reads copy p/2 through its
// port p%2. A write goes to all m copies, so they always hold the same data.
class CoordinateMemory {
public:
    // words_per_primitive: the block RAM aspect's depth (NumberFormat::block_ram_layout).
    CoordinateMemory(uint32_t copies, uint32_t depth, uint32_t words_per_primitive = BlockRam::kWords);

    uint32_t copies() const { return static_cast<uint32_t>(copies_.size()); }
    uint32_t ports() const { return 2 * copies(); }
    uint32_t depth() const { return depth_; }
    // Block RAM primitives this memory uses: m * ceil(depth / words per primitive).
    uint32_t block_rams() const { return copies() * copies_.front().primitives(); }

    void write(uint32_t address, uint32_t word);

    // One clock edge on a port with its enable high (one cycle of read latency).
    void clock_read(uint32_t port, uint32_t address) {
        copies_[port >> 1].clock_read(static_cast<int>(port & 1), address);
    }
    uint32_t output(uint32_t port) const {
        return copies_[port >> 1].output(static_cast<int>(port & 1));
    }
    // Contents as the host sees them (copy 0; all copies are equal).
    uint32_t peek(uint32_t address) const { return copies_.front().peek(address); }

private:
    uint32_t depth_;
    std::vector<CascadedBlockRam> copies_;
};

}  // namespace cdvp
