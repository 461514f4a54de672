#include "models/pair_collector/pair_collector.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

TEST(PairCollector, DrainsAtTheConfiguredRateInOrder) {
    PairCollector c({8, 2, 100});
    c.push(3, 4, 0b1011);  // lanes 0, 1, 3 -> (3,4) (3,5) (3,7)
    EXPECT_EQ(c.fifo_level(), 3u);
    EXPECT_EQ(c.fifo_free(), 5u);
    c.drain();
    EXPECT_EQ(c.buffer_count(), 2u);
    EXPECT_EQ(c.fifo_level(), 1u);
    c.drain();
    ASSERT_EQ(c.buffer_count(), 3u);
    EXPECT_EQ(c.buffer_entry(0), (IndexPair{3, 4}));
    EXPECT_EQ(c.buffer_entry(1), (IndexPair{3, 5}));
    EXPECT_EQ(c.buffer_entry(2), (IndexPair{3, 7}));
    EXPECT_EQ(c.total_pairs(), 3u);
}

TEST(PairCollector, FifoWrapsAround) {
    PairCollector c({4, 1, 1000});
    uint32_t expected_next = 1;
    for (uint32_t round = 0; round < 10; ++round) {
        c.push(0, 1 + 3 * round, 0b111);
        for (int k = 0; k < 3; ++k) c.drain();
    }
    ASSERT_EQ(c.buffer_count(), 30u);
    for (uint32_t k = 0; k < 30; ++k) EXPECT_EQ(c.buffer_entry(k).second, expected_next++);
}

TEST(PairCollector, FullBufferBlocksTheDrainUntilCleared) {
    PairCollector c({8, 4, 3});
    c.push(0, 1, 0b11111);
    EXPECT_FALSE(c.drain_blocked());
    c.drain();
    EXPECT_EQ(c.buffer_count(), 3u) << "the buffer takes only what fits";
    EXPECT_EQ(c.fifo_level(), 2u);
    EXPECT_TRUE(c.drain_blocked());
    c.clear_buffer();
    EXPECT_FALSE(c.drain_blocked());
    c.drain();
    EXPECT_EQ(c.buffer_count(), 2u);
    EXPECT_EQ(c.buffer_entry(1), (IndexPair{0, 5}));
    EXPECT_EQ(c.total_pairs(), 5u);
}

TEST(PairCollector, RejectsZeroSizes) {
    EXPECT_THROW(PairCollector({0, 1, 1}), std::invalid_argument);
    EXPECT_THROW(PairCollector({1, 0, 1}), std::invalid_argument);
    EXPECT_THROW(PairCollector({1, 1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace cdvp
