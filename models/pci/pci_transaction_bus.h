// Conventional PCI at the transaction level (plain C++): masters arbitrate
// for one shared bus clock by clock, tenure by tenure, under PCI 2.2's rules,
// so a transfer of the board's is timed against other devices' traffic.
// The fast level is PciTiming (bus_timing.h); docs/bus_models.md compares them.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "models/pci/background_traffic.h"
#include "models/pci/bus_timing.h"

namespace cdvp {

// What the measured master does: the board's DMA engine moving bytes, or the
// CPU (through the host bridge) reading or writing one board register.
struct PciTransfer {
    enum class Kind { kDma, kPioRead, kPioWrite };
    Kind kind = Kind::kDma;
    uint64_t bytes = 4;
    Direction direction = Direction::kToBoard;
};

// One bus tenure of a master: from its address phase to its last data phase.
struct PciTenure {
    uint64_t address_clock = 0;
    uint64_t end_clock = 0;   // the clock after its last data phase (or its retry)
    uint64_t data_phases = 0;
    bool retried = false;     // the target could not meet the 16-clock initial latency
    bool cut_by_timer = false;  // the latency timer ended it before the burst's end
};

struct PciOutcome {
    uint64_t request_clock = 0;  // REQ# first asserted
    uint64_t done_clock = 0;     // the bus idle again after its last tenure (turnaround included)
    std::vector<PciTenure> tenures;  // the measured master's
    uint64_t retries() const;
    uint64_t clocks() const { return done_clock - request_clock; }
};

// PCI 2.2's limit on a target's initial latency; a slower target retries.
constexpr uint32_t kPciMaxInitialLatencyClocks = 16;

class PciTransactionBus {
public:
    // Latencies beyond 16 clocks are allowed here (they cause retries);
    // PciTiming's validate() forbids them for the formula.
    PciTransactionBus(const PciConfig& config, std::vector<BusLoad> background);
    // Background masters run from clock 0; the transfer is requested at start_clock.
    PciOutcome run(const PciTransfer& transfer, uint64_t start_clock) const;
    double clock_ns() const { return 1000.0 / config_.clock_mhz; }
    const PciConfig& config() const { return config_; }

private:
    PciConfig config_;
    std::vector<BusLoad> background_;
};

// BusTiming at the transaction level. Each DMA time is the mean over
// kStartPhases start times, one at each phase of a background period and
// each in a different period (after a warm-up of kWarmupPeriods), memoized per (bytes, direction).
class PciTransactionTiming : public BusTiming {
public:
    static constexpr int kStartPhases = 64;
    static constexpr int kWarmupPeriods = 4;
    PciTransactionTiming(const PciConfig& config, const BusLoad& load);
    std::string describe() const override;
    double pio_read_ns() const override;
    double pio_write_ns() const override;
    double dma_ns(uint64_t bytes, Direction direction) const override;
    double interrupt_ns() const override { return bus_.config().interrupt_ns; }  // INTA# is a side-band wire
    uint64_t dma_transaction_bytes(Direction direction) const override;

private:
    double mean_ns(const PciTransfer& transfer) const;
    PciTiming formula_;  // the tenure size a DMA descriptor is cut to, as the fast level gives it
    PciTransactionBus bus_;
    BusLoad load_;
    mutable std::mutex mutex_;
    mutable std::map<std::pair<uint64_t, int>, double> memo_;  // (bytes, kind x direction) -> ns
};

}  // namespace cdvp
