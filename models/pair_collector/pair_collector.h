// Collects lane hits as (i, j) pairs: a pair FIFO that drains into the pair buffer.
#pragma once

#include <cstdint>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp {

struct PairCollectorConfig {
    // Pairs the FIFO holds. Must be >= 2m-1 so one cycle's hits always fit an
    // empty FIFO. Default: one 512-deep block-RAM FIFO (assumption).
    uint32_t fifo_depth = 512;
    // Pairs moved from the FIFO to the pair buffer each cycle. Default 1: one
    // 64-bit write a cycle into the on-board pair memory (assumption).
    uint32_t drain_per_cycle = 1;
    // Pairs the pair buffer holds before the board pauses for the host to
    // drain it. Default 262144: one 2 MiB ZBT SSRAM bank of the ADM-XRC-II
    // holding 64-bit pair entries (assumption).
    uint32_t buffer_depth = 262144;
};

// The FIFO takes up to 2m-1 pairs a cycle and is never overrun: the board
// holds its pipeline while the FIFO lacks room (back-pressure). The buffer
// never drops a pair either: when a pair must move and the buffer is full,
// drain_blocked() tells the board to pause until the host empties it.
class PairCollector {
public:
    explicit PairCollector(const PairCollectorConfig& config);

    // Clears FIFO and buffer for a new sweep.
    void reset();

    uint32_t fifo_level() const { return fifo_level_; }
    uint32_t fifo_free() const { return fifo_depth_ - fifo_level_; }
    bool drain_blocked() const { return fifo_level_ > 0 && buffer_.size() == buffer_depth_; }

    // Moves up to drain_per_cycle pairs from the FIFO into the buffer.
    void drain();
    // Pushes one pair per set bit of hits: bit k pairs row with first_column + k.
    // The caller guarantees popcount(hits) <= fifo_free().
    void push(uint32_t row, uint32_t first_column, uint64_t hits);
    // Pushes `count` pairs as they are (a grid board's lanes pair boxes that
    // are not neighbours in memory). The caller guarantees count <= fifo_free().
    void push_pairs(const IndexPair* pairs, uint32_t count);

    // The pair buffer as the host reads it.
    uint32_t buffer_count() const { return static_cast<uint32_t>(buffer_.size()); }
    uint32_t buffer_depth() const { return buffer_depth_; }
    const IndexPair& buffer_entry(uint32_t index) const { return buffer_[index]; }
    // The host has read the buffer: it may be refilled.
    void clear_buffer() { buffer_.clear(); }
    // Keeps the first `count` entries (an aborted sweep's buffer at the abort).
    void truncate_buffer(uint32_t count) {
        if (count < buffer_.size()) buffer_.resize(count);
    }

    // Pairs found since reset (all that ever entered the FIFO).
    uint64_t total_pairs() const { return total_pairs_; }

private:
    uint32_t fifo_depth_;
    uint32_t drain_per_cycle_;
    uint32_t buffer_depth_;
    std::vector<IndexPair> fifo_;  // ring of fifo_depth_ entries
    uint32_t fifo_head_ = 0;
    uint32_t fifo_level_ = 0;
    std::vector<IndexPair> buffer_;
    uint64_t total_pairs_ = 0;
};

}  // namespace cdvp
