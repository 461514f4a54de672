// PCI and PCIe timing against figures computed by hand.
#include "models/pci/bus_timing.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

constexpr double kClock33 = 1000.0 / 33.333;  // 30.0003 ns

TEST(PciTiming, SingleAccessesFromBusCycles) {
    const PciTiming pci{PciConfig{}};
    // Read: arbitration 2 + address 1 + target latency 8 + data 1 + turnaround 1.
    EXPECT_EQ(pci.single_read_clocks(), 13u);
    EXPECT_NEAR(pci.pio_read_ns(), 200.0 + 13 * kClock33, 1e-9);  // ~590 ns, within the era's 0.5-1 us
    // Posted write: 2 + 1 + 2 + 1 + 1.
    EXPECT_EQ(pci.single_write_clocks(), 7u);
    EXPECT_NEAR(pci.pio_write_ns(), 7 * kClock33, 1e-9);
}

TEST(PciTiming, BurstsAreCutByBurstLimitAndLatencyTimer) {
    const PciTiming pci{PciConfig{}};
    // Reads of host memory: 128-byte bursts = 32 data phases; timer allows 64-1-12 = 51.
    EXPECT_EQ(pci.data_phases_per_tenure(Direction::kToBoard), 32u);
    // Writes to host memory: 256-byte bursts = 64 phases, but the timer allows 64-1-2 = 61.
    EXPECT_EQ(pci.data_phases_per_tenure(Direction::kToHost), 61u);
    // 4000 bytes = 1000 phases. To board: 32 tenures of (2+1+12+1) overhead.
    EXPECT_EQ(pci.dma_clocks(4000, Direction::kToBoard), 32u * 16u + 1000u);
    // To host: ceil(1000/61) = 17 tenures of (2+1+2+1).
    EXPECT_EQ(pci.dma_clocks(4000, Direction::kToHost), 17u * 6u + 1000u);
    EXPECT_NEAR(pci.dma_ns(4000, Direction::kToHost), 1102 * kClock33, 1e-6);  // ~121 MB/s
    EXPECT_EQ(pci.dma_clocks(0, Direction::kToHost), 0u);
    EXPECT_EQ(pci.dma_clocks(1, Direction::kToHost), 7u) << "a partial word still takes a data phase";
}

TEST(PciTiming, WaitStatesShortenTenuresAndLengthenPhases) {
    PciConfig config;
    config.wait_states = 1;
    const PciTiming pci{config};
    EXPECT_EQ(pci.data_phases_per_tenure(Direction::kToHost), 30u);  // (64-1-2)/2
    // 1000 phases in 34 tenures: 34*6 overhead + 1000 phases + 966 wait states.
    EXPECT_EQ(pci.dma_clocks(4000, Direction::kToHost), 34u * 6u + 1000u + 966u);
}

TEST(PciTiming, SixtyFourBitSixtySixIsLimitedByTheLocalBus) {
    PciConfig config;
    config.width_bits = 64;
    config.clock_mhz = 66.667;
    const PciTiming pci{config};
    // 500 phases in 16 tenures of 32 (256-byte bursts): 16*6 + 500 = 596 clocks = ~8.9 us...
    EXPECT_EQ(pci.dma_clocks(4000, Direction::kToHost), 596u);
    // ...but the 32-bit/66 MHz local bus needs 4000/0.264 = 15.15 us.
    EXPECT_NEAR(pci.dma_ns(4000, Direction::kToHost), 4000 / 0.264, 1e-6);
}

TEST(PciTiming, RejectsSettingsOutsidePci22) {
    PciConfig config;
    config.width_bits = 48;
    EXPECT_THROW(PciTiming{config}, std::invalid_argument);
    config = PciConfig{};
    config.board_read_latency_clocks = 17;
    EXPECT_THROW(PciTiming{config}, std::invalid_argument);
    config = PciConfig{};
    config.wait_states = 9;
    EXPECT_THROW(PciTiming{config}, std::invalid_argument);
}

TEST(PcieTiming, LinkRateAfterEncodingAndPacketOverhead) {
    const PcieTiming pcie{PcieConfig{}};
    // 8 GT/s * 8 lanes * 128/130 / 8 bits = 7.877 B/ns; * 256/(256+24) = 7.202 B/ns.
    EXPECT_NEAR(pcie.link_bytes_per_ns(), 8.0 * 8 * 128 / 130 / 8 * 256 / 280, 1e-9);
    // The 128-bit/250 MHz fabric (4 B/ns) is the slower side.
    EXPECT_NEAR(pcie.dma_ns(4000, Direction::kToHost), 1000.0, 1e-9);
    EXPECT_NEAR(pcie.dma_ns(4000, Direction::kToBoard), 900.0 + 1000.0, 1e-9) << "reads wait for a completion";
    EXPECT_EQ(pcie.dma_ns(0, Direction::kToBoard), 0.0);
}

}  // namespace
}  // namespace cdvp
