// The PCIe TLP level: packet splits, credits, replays and the link rate
// against the formula's.
#include "models/pci/pcie_tlp_link.h"

#include <gtest/gtest.h>

namespace cdvp {
namespace {

// A card whose fabric outruns the link, so the link alone sets the pace.
PcieConfig fast_fabric() {
    PcieConfig config;
    config.local_bus = LocalBusConfig{1024, 1000.0};
    return config;
}

PcieOutcome dma(const PcieConfig& pcie, const PcieLinkConfig& link, uint64_t bytes, Direction d, uint64_t address = 0) {
    return PcieTlpLink(pcie, link, BusLoad{}).dma(bytes, d, 0.0, address);
}

TEST(PcieTlpLink, WritesAreSplitAtMaxPayloadBoundaries) {
    EXPECT_EQ(dma(fast_fabric(), {}, 4096, Direction::kToHost).requests, 16u);  // 4096 / 256
    EXPECT_EQ(dma(fast_fabric(), {}, 4096, Direction::kToHost, 100).requests, 17u) << "156 bytes up to the first boundary";
    PcieConfig small = fast_fabric();
    small.max_payload_bytes = 128;
    EXPECT_EQ(dma(small, {}, 4096, Direction::kToHost).requests, 32u);
}

TEST(PcieTlpLink, ReadsAreSplitByMaxReadRequestAndCompletionBoundary) {
    const PcieOutcome aligned = dma(fast_fabric(), {}, 4096, Direction::kToBoard);
    EXPECT_EQ(aligned.requests, 8u);       // 4096 / 512
    EXPECT_EQ(aligned.completions, 64u);   // 4096 / 64
    const PcieOutcome offset = dma(fast_fabric(), {}, 4096, Direction::kToBoard, 32);
    EXPECT_EQ(offset.requests, 9u);
    EXPECT_EQ(offset.completions, 65u) << "a 32-byte completion up to the first RCB boundary, then 63 whole";
    PcieLinkConfig rcb128;
    rcb128.read_completion_boundary_bytes = 128;
    EXPECT_EQ(dma(fast_fabric(), rcb128, 4096, Direction::kToBoard).completions, 32u);
    EXPECT_LT(dma(fast_fabric(), rcb128, 65536, Direction::kToBoard).ns, dma(fast_fabric(), {}, 65536, Direction::kToBoard).ns)
        << "fewer completion headers";
}

TEST(PcieTlpLink, SmallCreditPoolsStallTheTransfer) {
    const PcieOutcome roomy = dma(fast_fabric(), {}, 65536, Direction::kToHost);
    EXPECT_EQ(roomy.credit_stall_ns, 0.0);
    PcieLinkConfig tight;
    tight.posted_header_credits = 2;
    tight.posted_data_credits = 32;  // two max payloads in flight, 500 ns to get them back
    const PcieOutcome stalled = dma(fast_fabric(), tight, 65536, Direction::kToHost);
    EXPECT_GT(stalled.credit_stall_ns, 0.0);
    EXPECT_GT(stalled.ns, 3 * roomy.ns);

    PcieLinkConfig tight_reads;
    tight_reads.completion_header_credits = 8;
    tight_reads.completion_data_credits = 32;  // one 512-byte request at a time
    const PcieOutcome reads = dma(fast_fabric(), tight_reads, 65536, Direction::kToBoard);
    EXPECT_GT(reads.credit_stall_ns, 0.0);
    EXPECT_GT(reads.ns, 2 * dma(fast_fabric(), {}, 65536, Direction::kToBoard).ns);
}

TEST(PcieTlpLink, BitErrorsCauseReplaysThatCostTime) {
    const PcieOutcome clean = dma(fast_fabric(), {}, 1 << 20, Direction::kToHost);
    EXPECT_EQ(clean.replays, 0u);
    PcieLinkConfig noisy;
    noisy.bit_error_rate = 1e-6;  // ~2e-4 a 280-byte TLP: about 9 of 4096
    const PcieOutcome replayed = dma(fast_fabric(), noisy, 1 << 20, Direction::kToHost);
    EXPECT_GT(replayed.replays, 0u);
    EXPECT_GT(replayed.ns, clean.ns);
    EXPECT_EQ(replayed.ns, dma(fast_fabric(), noisy, 1 << 20, Direction::kToHost).ns) << "deterministic";
}

TEST(PcieTlpLink, LongWritesRunAtTheFormulasLinkRate) {
    // Posted writes of whole max payloads: each TLP is payload + 16 + 8 bytes
    // on the wire, the formula's payload / (payload + 24); ACKs and UpdateFCs
    // travel the other way. Tolerance 0.1% (start-up and the last packet).
    for (const double rate : {2.5, 5.0, 8.0, 16.0}) {
        PcieConfig config = fast_fabric();
        config.gigatransfers_per_s = rate;
        config.encoding_efficiency = rate <= 5.0 ? 0.8 : 128.0 / 130.0;
        for (const uint32_t lanes : {1u, 4u, 8u, 16u}) {
            config.lanes = lanes;
            const uint64_t bytes = 4 << 20;
            const double measured = bytes / dma(config, {}, bytes, Direction::kToHost).ns;
            EXPECT_NEAR(measured / PcieTiming(config).link_bytes_per_ns(), 1.0, 1e-3) << rate << " GT/s x" << lanes;
        }
    }
}

TEST(PcieTlpLink, LongReadsRunAtTheCompletionsRateBelowTheFormulas) {
    // A 512-byte request comes back as eight 64-byte completions (12 + 8
    // bytes each beyond the data) after its 8-byte ACK: 512 of every 680
    // bytes down the link, where the formula assumes 256 of 280.
    const PcieConfig config = fast_fabric();
    const PcieTlpLink link(config, {}, BusLoad{});
    const uint64_t bytes = 4 << 20;
    const PcieOutcome out = link.dma(bytes, Direction::kToBoard, 0.0);
    // Within 0.2%: the first round trip (0.9 us of 710). 16 KiB of completion
    // credits cover the round trip, so the link, not the credits, sets the pace.
    EXPECT_NEAR(bytes / out.ns / (link.bytes_per_ns() * 512.0 / 680.0), 1.0, 2e-3);
    EXPECT_LT(bytes / out.ns, 0.85 * PcieTiming(config).link_bytes_per_ns());
}

TEST(PcieTlpTiming, IdleLinkPioEqualsTheFormulaAndDmaIsClose) {
    const PcieConfig config;  // pcie-gen3-x8: its fabric, 16 B x 250 MHz, sets the DMA pace
    const PcieTiming formula{config};
    const PcieTlpTiming tlp{config, {}, BusLoad{}};
    EXPECT_EQ(formula.pio_read_ns(), tlp.pio_read_ns());
    EXPECT_EQ(formula.pio_write_ns(), tlp.pio_write_ns());
    EXPECT_EQ(formula.interrupt_ns(), tlp.interrupt_ns());
    // The fabric-bound transfer pipelines through the link: the TLP level
    // adds the last packet's wire time (a write: 280 bytes, 35.5 ns) or the
    // request's, its ACK's and first completion's (a read: 24 + 8 + 84 bytes, 14.7 ns).
    for (const uint64_t bytes : {4096ull, 65536ull, 1ull << 20}) {
        EXPECT_NEAR(tlp.dma_ns(bytes, Direction::kToHost) - formula.dma_ns(bytes, Direction::kToHost), 35.5, 0.1) << bytes;
        EXPECT_NEAR(tlp.dma_ns(bytes, Direction::kToBoard) - formula.dma_ns(bytes, Direction::kToBoard), 14.7, 0.1) << bytes;
    }
}

TEST(PcieTlpTiming, CostRisesWithBackgroundLoad) {
    const PcieConfig config = fast_fabric();
    const double peak = PcieTlpLink(config, {}, BusLoad{}).bytes_per_ns() * 1e9;
    for (const Direction d : {Direction::kToBoard, Direction::kToHost}) {
        double previous = 0;
        for (const double fraction : {0.0, 0.1, 0.3, 0.6}) {
            BusLoad load;
            load.bytes_per_s = fraction * peak;
            load.direction = d;
            const double ns = PcieTlpTiming(config, {}, load).dma_ns(65536, d);
            EXPECT_GE(ns, previous) << fraction;
            previous = ns;
        }
        EXPECT_GT(previous, 1.3 * PcieTlpTiming(config, {}, BusLoad{}).dma_ns(65536, d));
    }
}

TEST(PcieTlpLink, RefusesBadValuesNamingTheSetting) {
    PcieLinkConfig link;
    link.read_completion_boundary_bytes = 96;
    try {
        PcieTlpLink(PcieConfig{}, link, BusLoad{});
        FAIL() << "accepted a 96-byte RCB";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "bus.read_completion_boundary_bytes: expected 64 or 128, got 96");
    }
    link = PcieLinkConfig{};
    link.posted_data_credits = 8;
    try {
        PcieTlpLink(PcieConfig{}, link, BusLoad{});
        FAIL() << "accepted less than one max payload of credits";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "bus.posted_data_credits: expected at least 16 (one max payload of 256 bytes), got 8");
    }
}

}  // namespace
}  // namespace cdvp
