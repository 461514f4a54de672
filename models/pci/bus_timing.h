// Host-bus timing arithmetic (plain C++): what a programmed access, a DMA
// transfer and an interrupt cost in time on a PCI or PCIe link.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace cdvp {

enum class Direction { kToBoard, kToHost };

// One bus, as the platform sees it. Times in nanoseconds.
class BusTiming {
public:
    virtual ~BusTiming() = default;
    virtual std::string describe() const = 0;
    // CPU stall for one 32-bit read of a board register (a round trip).
    virtual double pio_read_ns() const = 0;
    // CPU time for one 32-bit write: posted, but a stream of writes drains
    // at the bus's rate, so each costs the write transaction's bus time.
    virtual double pio_write_ns() const = 0;
    // Bus-master DMA of bytes between host memory and board memory, from
    // the bridge's start to its last data phase.
    virtual double dma_ns(uint64_t bytes, Direction direction) const = 0;
    // From the board raising its interrupt to the driver's handler running.
    virtual double interrupt_ns() const = 0;
    // Bytes one bus-master tenure (one transaction) of a DMA carries at most.
    virtual uint64_t dma_transaction_bytes(Direction direction) const = 0;
};

// No host-bus cost at all: the board alone, as if the host were on chip.
class IdealBusTiming : public BusTiming {
public:
    std::string describe() const override { return "untimed host bus"; }
    double pio_read_ns() const override { return 0.0; }
    double pio_write_ns() const override { return 0.0; }
    double dma_ns(uint64_t, Direction) const override { return 0.0; }
    double interrupt_ns() const override { return 0.0; }
    uint64_t dma_transaction_bytes(Direction) const override { return 4096; }
};

// The bus a platform is given, or the ideal bus when it is given none.
inline std::shared_ptr<const BusTiming> bus_or_ideal(std::shared_ptr<const BusTiming> bus) {
    return bus ? std::move(bus) : std::make_shared<IdealBusTiming>();
}

// The board's local bus between the PCI bridge and the FPGA: DMA cannot move
// data faster than it.
struct LocalBusConfig {
    uint32_t width_bits = 32;  // PLX PCI9656 local bus: 32 bits
    double clock_mhz = 66.0;   // up to 66 MHz (ADM-XRC-II, programmable)
    double bytes_per_ns() const { return width_bits / 8.0 * clock_mhz / 1000.0; }
};

// Conventional PCI, timed from bus cycles (PCI 2.2 rules; defaults are the
// 32-bit/33 MHz desktop of the paper; see platform/boards/ for sources).
struct PciConfig {
    uint32_t width_bits = 32;                  // 32 or 64
    double clock_mhz = 33.333;                 // 33.333 or 66.667
    uint32_t arbitration_clocks = 2;           // REQ# to GNT# on an idle bus
    uint32_t address_phase_clocks = 1;
    uint32_t board_read_latency_clocks = 8;    // bridge as target: address to first data of a read (<= 16)
    uint32_t board_write_latency_clocks = 2;   // bridge as target: posted write, DEVSEL + TRDY
    uint32_t host_read_latency_clocks = 12;    // host bridge as target of a DMA read of host memory
    uint32_t host_write_latency_clocks = 2;    // host bridge as target of a DMA write (posted)
    uint32_t wait_states = 0;                  // per data phase after the first (<= 8)
    uint32_t turnaround_clocks = 1;            // idle clock between transactions
    uint32_t latency_timer_clocks = 64;        // a master's tenure ends when it expires
    uint32_t dma_read_burst_bytes = 128;       // bridge DMA: 16 quadwords per read burst
    uint32_t dma_write_burst_bytes = 256;      // bridge DMA: 32 quadwords per write burst
    double host_pio_overhead_ns = 200.0;       // CPU to host bridge and back, beyond the PCI cycles
    double interrupt_ns = 10000.0;             // INTA# delivery plus handler entry
    LocalBusConfig local_bus;
    void validate() const;  // std::invalid_argument "SETTING: expected ..., got ..."
};

class PciTiming : public BusTiming {
public:
    explicit PciTiming(const PciConfig& config);
    std::string describe() const override;
    double pio_read_ns() const override;
    double pio_write_ns() const override;
    double dma_ns(uint64_t bytes, Direction direction) const override;
    double interrupt_ns() const override { return config_.interrupt_ns; }
    uint64_t dma_transaction_bytes(Direction direction) const override;

    // The cycle arithmetic behind the times (in PCI clocks).
    uint64_t single_read_clocks() const;   // one data phase, board as target
    uint64_t single_write_clocks() const;
    // Data phases one DMA tenure may carry: the burst limit, cut further by the latency timer.
    uint64_t data_phases_per_tenure(Direction direction) const;
    uint64_t dma_clocks(uint64_t bytes, Direction direction) const;
    double clock_ns() const { return 1000.0 / config_.clock_mhz; }

private:
    PciConfig config_;
};

// PCI Express, timed from link rate and packet overhead (the what-if card).
struct PcieConfig {
    double gigatransfers_per_s = 8.0;    // Gen3
    uint32_t lanes = 8;
    double encoding_efficiency = 128.0 / 130.0;
    uint32_t max_payload_bytes = 256;
    uint32_t max_read_request_bytes = 512;
    uint32_t tlp_overhead_bytes = 24;    // framing, sequence number, 3-4 DW header, LCRC, plus DLLP share
    double read_round_trip_ns = 900.0;   // a non-posted read: request to completion
    double posted_write_ns = 100.0;      // CPU cost of one posted MMIO write
    double interrupt_ns = 3000.0;        // MSI delivery plus handler entry
    LocalBusConfig local_bus{128, 250.0};  // the card's fabric datapath
    void validate() const;
};

class PcieTiming : public BusTiming {
public:
    explicit PcieTiming(const PcieConfig& config);
    std::string describe() const override;
    double pio_read_ns() const override { return config_.read_round_trip_ns; }
    double pio_write_ns() const override { return config_.posted_write_ns; }
    double dma_ns(uint64_t bytes, Direction direction) const override;
    double interrupt_ns() const override { return config_.interrupt_ns; }
    uint64_t dma_transaction_bytes(Direction direction) const override;
    // Payload bytes per ns on the link after encoding and TLP overhead.
    double link_bytes_per_ns() const;

private:
    PcieConfig config_;
};

}  // namespace cdvp
