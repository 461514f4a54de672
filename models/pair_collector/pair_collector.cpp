#include "models/pair_collector/pair_collector.h"

#include <algorithm>
#include <stdexcept>

namespace cdvp {

PairCollector::PairCollector(const PairCollectorConfig& config)
    : fifo_depth_(config.fifo_depth),
      drain_per_cycle_(config.drain_per_cycle),
      buffer_depth_(config.buffer_depth),
      fifo_(config.fifo_depth) {
    if (fifo_depth_ == 0 || drain_per_cycle_ == 0 || buffer_depth_ == 0) {
        throw std::invalid_argument("pair collector FIFO depth, drain rate and buffer depth must be >= 1");
    }
    buffer_.reserve(std::min<uint32_t>(buffer_depth_, 1u << 16));
}

void PairCollector::reset() {
    fifo_head_ = 0;
    fifo_level_ = 0;
    buffer_.clear();
    total_pairs_ = 0;
}

void PairCollector::drain() {
    const uint32_t room = buffer_depth_ - static_cast<uint32_t>(buffer_.size());
    uint32_t moves = std::min({drain_per_cycle_, fifo_level_, room});
    for (; moves > 0; --moves) {
        buffer_.push_back(fifo_[fifo_head_]);
        fifo_head_ = fifo_head_ + 1 == fifo_depth_ ? 0 : fifo_head_ + 1;
        --fifo_level_;
    }
}

void PairCollector::push(uint32_t row, uint32_t first_column, uint64_t hits) {
    uint32_t tail = fifo_head_ + fifo_level_;
    if (tail >= fifo_depth_) tail -= fifo_depth_;
    while (hits != 0) {
        const uint32_t lane = static_cast<uint32_t>(__builtin_ctzll(hits));
        hits &= hits - 1;
        fifo_[tail] = IndexPair{row, first_column + lane};
        tail = tail + 1 == fifo_depth_ ? 0 : tail + 1;
        ++fifo_level_;
        ++total_pairs_;
    }
}

void PairCollector::push_pairs(const IndexPair* pairs, uint32_t count) {
    uint32_t tail = fifo_head_ + fifo_level_;
    if (tail >= fifo_depth_) tail -= fifo_depth_;
    for (uint32_t k = 0; k < count; ++k) {
        fifo_[tail] = pairs[k];
        tail = tail + 1 == fifo_depth_ ? 0 : tail + 1;
    }
    fifo_level_ += count;
    total_pairs_ += count;
}

}  // namespace cdvp
