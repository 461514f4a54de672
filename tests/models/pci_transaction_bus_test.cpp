// The PCI transaction level: exact against the formula on an idle bus, and
// the arbiter's, latency timer's and retries' effects under load.
#include "models/pci/pci_transaction_bus.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

constexpr double kPci33PeakBytesPerS = 4 * 33.333e6;

BusLoad load_of(double fraction, uint32_t burst = 512, Direction direction = Direction::kToHost) {
    BusLoad load;
    load.bytes_per_s = fraction * kPci33PeakBytesPerS;
    load.burst_bytes = burst;
    load.direction = direction;
    return load;
}

// Sizes from one byte to 40 KB: partial words, one and many tenures.
std::vector<uint64_t> sizes() {
    std::vector<uint64_t> all;
    for (uint64_t b = 1; b <= 300; ++b) all.push_back(b);
    for (uint64_t b = 301; b <= 40000; b = b * 9 / 8 + 7) all.push_back(b);
    return all;
}

TEST(PciTransactionTiming, EqualsTheFormulaExactlyOnAnIdleBusWhenBurstsEndBeforeTheTimer) {
    // Bursts that end before the latency timer would: the formula's timer
    // cut never applies. 32-bit/33 with 48-phase write bursts; with 2 wait
    // states and a 255-clock timer; 64-bit/66 (its local bus sets the pace).
    PciConfig narrow, waiting, wide;
    narrow.dma_write_burst_bytes = waiting.dma_write_burst_bytes = 192;
    waiting.wait_states = 2;
    waiting.latency_timer_clocks = 255;
    wide.width_bits = 64;
    wide.clock_mhz = 66.667;
    for (const PciConfig& config : {narrow, waiting, wide}) {
        const PciTiming formula{config};
        const PciTransactionTiming transaction{config, BusLoad{}};
        for (const Direction d : {Direction::kToBoard, Direction::kToHost}) {
            for (const uint64_t bytes : sizes()) {
                ASSERT_EQ(formula.dma_ns(bytes, d), transaction.dma_ns(bytes, d)) << bytes << " bytes";
            }
        }
        EXPECT_EQ(formula.pio_read_ns(), transaction.pio_read_ns());
        EXPECT_EQ(formula.pio_write_ns(), transaction.pio_write_ns());
        EXPECT_EQ(formula.interrupt_ns(), transaction.interrupt_ns());
        EXPECT_EQ(formula.dma_transaction_bytes(Direction::kToHost), transaction.dma_transaction_bytes(Direction::kToHost));
    }
}

TEST(PciTransactionTiming, OnAnIdleBusTheTimerDoesNotCutWhatTheFormulaCuts) {
    // The paper's bus: 256-byte write bursts are 64 phases, the formula cuts
    // them at the timer's 61; an idle bus removes no GNT#, so the transaction
    // level saves one tenure's overhead (2+1+2+1 clocks) per tenure saved.
    const PciConfig config;
    const PciTiming formula{config};
    const PciTransactionTiming transaction{config, BusLoad{}};
    const double clock = formula.clock_ns();
    for (const uint64_t bytes : sizes()) {
        const uint64_t phases = (bytes + 3) / 4;
        const uint64_t saved = (phases + 60) / 61 - (phases + 63) / 64;
        ASSERT_NEAR(formula.dma_ns(bytes, Direction::kToHost) - transaction.dma_ns(bytes, Direction::kToHost),
                    saved * 6 * clock, 1e-6) << bytes << " bytes";
        ASSERT_EQ(formula.dma_ns(bytes, Direction::kToBoard), transaction.dma_ns(bytes, Direction::kToBoard));
    }
}

TEST(PciTransactionTiming, CostRisesWithBackgroundLoad) {
    for (const LoadArrivals arrivals : {LoadArrivals::kPeriodic, LoadArrivals::kRandom}) {
        double previous_dma[2] = {0, 0}, previous_pio = 0;
        for (const double fraction : {0.0, 0.1, 0.2, 0.3, 0.45, 0.6}) {
            BusLoad load = load_of(fraction);
            load.arrivals = arrivals;
            const PciTransactionTiming bus{PciConfig{}, load};
            for (const Direction d : {Direction::kToBoard, Direction::kToHost}) {
                const double ns = bus.dma_ns(16000, d);
                EXPECT_GE(ns, previous_dma[d == Direction::kToHost]) << fraction;
                previous_dma[d == Direction::kToHost] = ns;
            }
            // A PIO read waits for at most one cut tenure: 64 samples of a random
            // load are too few to order neighbouring loads, so only periodic ones are held to it.
            if (arrivals == LoadArrivals::kPeriodic) {
                EXPECT_GE(bus.pio_read_ns(), previous_pio) << fraction;
            }
            previous_pio = bus.pio_read_ns();
        }
        BusLoad heavy = load_of(0.6);
        heavy.arrivals = arrivals;
        const PciTransactionTiming idle{PciConfig{}, BusLoad{}}, busy{PciConfig{}, heavy};
        EXPECT_GT(busy.dma_ns(16000, Direction::kToBoard), 1.5 * idle.dma_ns(16000, Direction::kToBoard));
        EXPECT_GT(busy.pio_read_ns(), idle.pio_read_ns());
    }
}

TEST(PciTransactionTiming, RepeatedCallsGiveTheSameTime) {
    const PciTransactionTiming bus{PciConfig{}, load_of(0.3)};
    const double first = bus.dma_ns(4000, Direction::kToBoard);
    EXPECT_EQ(first, bus.dma_ns(4000, Direction::kToBoard));
    EXPECT_EQ(first, PciTransactionTiming(PciConfig{}, load_of(0.3)).dma_ns(4000, Direction::kToBoard));
}

TEST(PciTransactionBus, TheLatencyTimerCutsALongBurstWhenAnotherMasterRequests) {
    PciConfig config;
    config.dma_write_burst_bytes = 4096;  // 1024 phases: one tenure on an idle bus
    const PciTransfer dma{PciTransfer::Kind::kDma, 4096, Direction::kToHost};
    const PciOutcome idle = PciTransactionBus(config, {}).run(dma, 0);
    ASSERT_EQ(idle.tenures.size(), 1u);
    EXPECT_EQ(idle.tenures[0].data_phases, 1024u);
    EXPECT_FALSE(idle.tenures[0].cut_by_timer);

    // A disk controller requesting at clock 0: GNT# goes at once, the timer
    // (64 clocks from FRAME#) leaves 64 - 1 - 2 = 61 data phases.
    const PciOutcome shared = PciTransactionBus(config, {load_of(0.3)}).run(dma, 0);
    ASSERT_GT(shared.tenures.size(), 1u);
    EXPECT_EQ(shared.tenures[0].data_phases, 61u);
    EXPECT_TRUE(shared.tenures[0].cut_by_timer);
    uint64_t phases = 0;
    for (const PciTenure& t : shared.tenures) phases += t.data_phases;
    EXPECT_EQ(phases, 1024u);
    // Hidden arbitration: the other master, granted during the board's tenure,
    // starts right after the turnaround; its 128-phase burst is cut too (the
    // board asks again), 1 + 2 + 61 clocks; then a turnaround and the board.
    EXPECT_EQ(shared.tenures[1].address_clock, shared.tenures[0].end_clock + 1 + 64 + 1);
    EXPECT_GT(shared.clocks(), idle.clocks());
}

TEST(PciTransactionBus, RoundRobinAlternatesBetweenRequestingMasters) {
    PciConfig config;
    config.dma_write_burst_bytes = 4096;
    // A master always requesting (more load than the bus carries) still lets the board in every other tenure.
    const PciOutcome out = PciTransactionBus(config, {load_of(2.0, 4096)}).run({PciTransfer::Kind::kDma, 4096, Direction::kToHost}, 1000);
    ASSERT_GT(out.tenures.size(), 2u);
    // Turnaround, the other's cut tenure (address 1 + latency 2 + 61 phases), turnaround.
    for (std::size_t k = 1; k < out.tenures.size(); ++k) {
        EXPECT_EQ(out.tenures[k].address_clock, out.tenures[k - 1].end_clock + 1 + 64 + 1) << k;
        EXPECT_EQ(out.tenures[k - 1].data_phases, 61u) << k;
    }
}

TEST(PciTransactionBus, ATargetSlowerThanSixteenClocksRetriesAndTheMasterReArbitrates) {
    PciConfig config;
    config.host_read_latency_clocks = 40;  // beyond PCI 2.2's 16: only the transaction level accepts it
    const PciOutcome out = PciTransactionBus(config, {}).run({PciTransfer::Kind::kDma, 4, Direction::kToBoard}, 0);
    // Attempt at clock 2 (data from 3, ready at 43): retried at 19; again at 22: retried at 39;
    // at 42 the delayed read's data is ready: first data at clock 44, idle at 46.
    ASSERT_EQ(out.tenures.size(), 3u);
    EXPECT_EQ(out.retries(), 2u);
    EXPECT_TRUE(out.tenures[0].retried);
    EXPECT_EQ(out.tenures[0].end_clock, 19u);
    EXPECT_EQ(out.tenures[2].address_clock, 42u);
    EXPECT_EQ(out.done_clock, 46u);
    config.host_read_latency_clocks = 16;
    EXPECT_EQ(PciTransactionBus(config, {}).run({PciTransfer::Kind::kDma, 4, Direction::kToBoard}, 0).retries(), 0u);
}

TEST(PciTransactionTiming, RefusesBadValuesNamingTheSetting) {
    BusLoad load = load_of(0.1);
    load.burst_bytes = 2;
    try {
        PciTransactionTiming bus{PciConfig{}, load};
        FAIL() << "accepted a 2-byte burst";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "bus.load_burst_bytes: expected 4 to 65536, got 2");
    }
    PciConfig config;
    config.wait_states = 9;
    EXPECT_THROW(PciTransactionTiming(config, BusLoad{}), std::invalid_argument);
}

}  // namespace
}  // namespace cdvp
