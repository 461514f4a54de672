// PCI Express at the transaction-layer-packet level (plain C++): a DMA is cut
// into TLPs by max payload size, max read request size and the read
// completion boundary; each TLP pays header, sequence number, LCRC and
// framing on the wire, waits for flow-control credits, and may be replayed
// after a bit error. The fast level is PcieTiming (bus_timing.h).
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <utility>

#include "models/pci/background_traffic.h"
#include "models/pci/bus_timing.h"

namespace cdvp {

// Sequence number 2, LCRC 4, framing 2 bytes a TLP beyond its header (pcie-bench's figures).
constexpr uint32_t kTlpLinkBytes = 8;
constexpr uint32_t kCompletionHeaderBytes = 12;  // a completion's header is always 3 DW
constexpr uint32_t kDllpBytes = 8;               // ACK, NAK, UpdateFC
constexpr uint32_t kCreditBytes = 16;            // one data credit: 4 DW

// What the TLP level adds to PcieConfig.
struct PcieLinkConfig {
    uint32_t tlp_header_bytes = 16;                // 4 DW: 64-bit host addresses (3 DW: 12)
    uint32_t read_completion_boundary_bytes = 64;  // completions split at RCB-aligned addresses
    uint32_t posted_header_credits = 64;           // the root complex's posted buffer (writes to the host)
    uint32_t posted_data_credits = 1024;           // in 16-byte units: 16 KiB
    uint32_t completion_header_credits = 256;      // the board's completion buffer (its DMA reads)
    uint32_t completion_data_credits = 1024;
    double credit_return_ns = 500.0;               // a TLP received to its credits back at the sender (UpdateFC)
    double bit_error_rate = 0.0;                   // per bit on the wire; a corrupt TLP is NAKed and replayed
    double replay_timer_ns = 2000.0;               // a replay when the NAK itself is lost
    uint64_t error_seed = 1;                       // of the deterministic error draws
    void validate(const PcieConfig& pcie) const;   // "bus.KEY: expected ..., got ..."
};

// A DMA on the link, as the tests and the bench see it.
struct PcieOutcome {
    double ns = 0;            // request of the first TLP to the last byte in the destination
    uint64_t requests = 0;    // read requests (reads) or write TLPs (writes) of the board
    uint64_t completions = 0; // completion TLPs (reads)
    uint64_t replays = 0;     // TLPs sent again after an error
    double credit_stall_ns = 0;  // time the board's TLPs waited for credits beyond their data
};

class PcieTlpLink {
public:
    PcieTlpLink(const PcieConfig& pcie, const PcieLinkConfig& link, const BusLoad& load);
    // A DMA of bytes from host address offset 'address' (RCB alignment), started at start_ns
    // with the background master running from time 0.
    PcieOutcome dma(uint64_t bytes, Direction direction, double start_ns, uint64_t address = 0) const;
    // The delay a single small TLP (a PIO access's) waits behind background traffic.
    double queueing_ns(uint32_t wire_bytes, Direction direction, double start_ns) const;
    double bytes_per_ns() const;  // raw, after the line code
    double ack_latency_ns() const;
    const PcieConfig& pcie() const { return pcie_; }
    const BusLoad& load() const { return load_; }

private:
    PcieConfig pcie_;
    PcieLinkConfig link_;
    BusLoad load_;
};

// BusTiming at the TLP level: times averaged over start phases like
// PciTransactionTiming, memoized per (bytes, direction).
class PcieTlpTiming : public BusTiming {
public:
    static constexpr int kStartPhases = 64;
    static constexpr int kWarmupPeriods = 4;
    PcieTlpTiming(const PcieConfig& pcie, const PcieLinkConfig& link, const BusLoad& load);
    std::string describe() const override;
    double pio_read_ns() const override;
    double pio_write_ns() const override;
    double dma_ns(uint64_t bytes, Direction direction) const override;
    double interrupt_ns() const override { return link_.pcie().interrupt_ns; }
    uint64_t dma_transaction_bytes(Direction direction) const override { return formula_.dma_transaction_bytes(direction); }

private:
    template <class F>
    double mean_over_phases(F time_at) const;
    PcieTiming formula_;
    PcieTlpLink link_;
    mutable std::mutex mutex_;
    mutable std::map<std::pair<uint64_t, int>, double> memo_;
};

}  // namespace cdvp
