#include "models/block_ram/block_ram.h"

#include <gtest/gtest.h>

#include "models/coordinate_memory/coordinate_memory.h"

namespace cdvp {
namespace {

TEST(BlockRam, ReadHasOneCycleLatencyAndHoldsWhenDisabled) {
    BlockRam ram;
    ram.write(7, 0xdeadbeef);
    ram.write(8, 0x12345678);
    EXPECT_EQ(ram.output(0), 0u) << "nothing registered before the first edge";
    ram.clock_read(0, 7);
    EXPECT_EQ(ram.output(0), 0xdeadbeefu);
    ram.write(7, 1);  // a write after the edge does not change the registered output
    EXPECT_EQ(ram.output(0), 0xdeadbeefu);
    ram.clock_read(1, 8);  // the other port is independent
    EXPECT_EQ(ram.output(0), 0xdeadbeefu);
    EXPECT_EQ(ram.output(1), 0x12345678u);
}

TEST(BlockRam, PrimitiveHolds512Words) {
    BlockRam ram;
    for (uint32_t a = 0; a < BlockRam::kWords; ++a) ram.write(a, a * 3 + 1);
    for (uint32_t a = 0; a < BlockRam::kWords; ++a) EXPECT_EQ(ram.peek(a), a * 3 + 1);
}

TEST(CascadedBlockRam, DepthComesFromTheScene) {
    EXPECT_EQ(CascadedBlockRam::primitives_for(0), 0u);
    EXPECT_EQ(CascadedBlockRam::primitives_for(1), 1u);
    EXPECT_EQ(CascadedBlockRam::primitives_for(512), 1u);
    EXPECT_EQ(CascadedBlockRam::primitives_for(513), 2u);
    EXPECT_EQ(CascadedBlockRam::primitives_for(2000), 4u);
    CascadedBlockRam ram(1500);
    EXPECT_EQ(ram.primitives(), 3u);
    for (uint32_t a = 0; a < 1500; ++a) ram.write(a, ~a);
    for (uint32_t a : {0u, 511u, 512u, 1023u, 1024u, 1499u}) {
        ram.clock_read(1, a);
        EXPECT_EQ(ram.output(1), ~a) << a;
    }
    EXPECT_THROW(ram.write(1500, 0), std::out_of_range);
}

TEST(CascadedBlockRam, NarrowerAspectsAreDeeperPrimitives) {
    EXPECT_EQ(CascadedBlockRam::primitives_for(2048, 2048), 1u);
    EXPECT_EQ(CascadedBlockRam::primitives_for(2049, 2048), 2u);
    EXPECT_EQ(CascadedBlockRam::primitives_for(1025, 1024), 2u);
    CascadedBlockRam ram(3000, 1024);
    EXPECT_EQ(ram.primitives(), 3u);
    for (uint32_t a = 0; a < 3000; ++a) ram.write(a, a ^ 0x5A5A);
    for (uint32_t a : {0u, 1023u, 1024u, 2047u, 2048u, 2999u}) {
        ram.clock_read(0, a);
        EXPECT_EQ(ram.output(0), a ^ 0x5A5A) << a;
    }
    EXPECT_EQ(CoordinateMemory(3, 3000, 2048).block_rams(), 3u * 2);
    EXPECT_THROW(CascadedBlockRam(10, 1000), std::invalid_argument);
}

TEST(CoordinateMemory, WriteReachesAllCopiesAnd2mPortsRead) {
    const uint32_t m = 4;
    CoordinateMemory memory(m, 600);
    EXPECT_EQ(memory.ports(), 2 * m);
    EXPECT_EQ(memory.block_rams(), m * 2);
    for (uint32_t a = 0; a < 600; ++a) memory.write(a, a + 100);
    // 2m different addresses in one cycle, each through its own copy and port.
    for (uint32_t p = 0; p < memory.ports(); ++p) memory.clock_read(p, 70 * p + 5);
    for (uint32_t p = 0; p < memory.ports(); ++p) EXPECT_EQ(memory.output(p), 70 * p + 105) << p;
    EXPECT_THROW(CoordinateMemory(0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace cdvp
