#include "models/pci/pci_transaction_bus.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "models/common/integer_math.h"

namespace cdvp {

namespace {

constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();

// A bus master as the arbiter sees it.
struct Master {
    uint64_t pending_phases = 0;  // data phases still to move
    uint64_t request_clock = kNever;  // REQ# asserted (while pending_phases > 0)
    uint64_t burst_phases = 1;    // at most this many a tenure (the burst boundary: disconnect)
    uint32_t latency = 0;         // the target's initial latency, clocks
    uint64_t ready_clock = kNever;  // a delayed transaction's data ready at the target
    // Background only: its arrivals, and phases a burst.
    bool background = false;
    ArrivalProcess arrivals{BusLoad{}};
    uint64_t next_arrival = kNever;
    uint64_t phases_per_arrival = 0;
    double clock_ns = 1;

    // Bursts that have arrived by 'clock' join the queue.
    void absorb(uint64_t clock) {
        while (background && next_arrival <= clock) {
            if (pending_phases == 0) request_clock = next_arrival;
            pending_phases += phases_per_arrival;
            next_arrival = to_clock(arrivals.next());
        }
    }
    // When it next wants the bus (kNever: not before its next arrival, if any).
    uint64_t wants_bus() const { return pending_phases > 0 ? request_clock : next_arrival; }
    uint64_t to_clock(double ns) const {
        return std::isinf(ns) ? kNever : static_cast<uint64_t>(std::ceil(ns / clock_ns - 1e-9));
    }
};

}  // namespace

uint64_t PciOutcome::retries() const {
    return static_cast<uint64_t>(std::count_if(tenures.begin(), tenures.end(), [](const PciTenure& t) { return t.retried; }));
}

PciTransactionBus::PciTransactionBus(const PciConfig& config, std::vector<BusLoad> background)
    : config_(config), background_(std::move(background)) {
    if (config_.width_bits != 32 && config_.width_bits != 64) {
        throw std::invalid_argument("pci.width_bits: expected 32 or 64, got " + std::to_string(config_.width_bits));
    }
    if (!(config_.clock_mhz >= 1 && config_.clock_mhz <= 133)) {
        throw std::invalid_argument("pci.clock_mhz: expected 1 to 133");
    }
    if (config_.dma_read_burst_bytes < config_.width_bits / 8 || config_.dma_write_burst_bytes < config_.width_bits / 8) {
        throw std::invalid_argument("pci.dma_*_burst_bytes: expected at least one data phase");
    }
    for (const BusLoad& load : background_) load.validate();
}

PciOutcome PciTransactionBus::run(const PciTransfer& transfer, uint64_t start_clock) const {
    const PciConfig& c = config_;
    const uint64_t width = c.width_bits / 8;
    const bool to_board = transfer.direction == Direction::kToBoard;
    std::vector<Master> masters(1 + background_.size());
    Master& board = masters[0];  // the measured master: the board's DMA engine or the host bridge's PIO
    board.pending_phases = transfer.kind == PciTransfer::Kind::kDma ? ceil_div(transfer.bytes, width) : 1;
    board.request_clock = start_clock;
    switch (transfer.kind) {
        case PciTransfer::Kind::kDma:
            board.burst_phases = std::max<uint64_t>(1, (to_board ? c.dma_read_burst_bytes : c.dma_write_burst_bytes) / width);
            board.latency = to_board ? c.host_read_latency_clocks : c.host_write_latency_clocks;
            break;
        case PciTransfer::Kind::kPioRead: board.latency = c.board_read_latency_clocks; break;
        case PciTransfer::Kind::kPioWrite: board.latency = c.board_write_latency_clocks; break;
    }
    for (std::size_t k = 0; k < background_.size(); ++k) {
        const BusLoad& load = background_[k];
        Master& m = masters[k + 1];
        m.background = true;
        m.clock_ns = clock_ns();
        m.arrivals = ArrivalProcess(load);
        m.next_arrival = m.to_clock(m.arrivals.next());
        m.phases_per_arrival = ceil_div(load.burst_bytes, width);
        m.burst_phases = m.phases_per_arrival;
        m.latency = load.direction == Direction::kToBoard ? c.host_read_latency_clocks : c.host_write_latency_clocks;
    }
    if (board.pending_phases == 0) return {start_clock, start_clock, {}};

    PciOutcome outcome;
    outcome.request_clock = start_clock;
    uint64_t bus_free = 0;   // the clock the bus is idle again
    std::size_t last = masters.size() - 1;  // the last master granted (round-robin)
    while (board.pending_phases > 0) {
        for (Master& m : masters) m.absorb(bus_free);
        // Round-robin among masters already requesting when the bus frees;
        // on an idle bus, the first to request.
        std::size_t chosen = masters.size();
        for (std::size_t step = 1; step <= masters.size() && chosen == masters.size(); ++step) {
            const std::size_t k = (last + step) % masters.size();
            if (masters[k].wants_bus() <= bus_free) chosen = k;
        }
        if (chosen == masters.size()) {
            uint64_t first = kNever;
            for (std::size_t step = 1; step <= masters.size(); ++step) {
                const std::size_t k = (last + step) % masters.size();
                if (masters[k].wants_bus() < first) first = masters[k].wants_bus(), chosen = k;
            }
            masters[chosen].absorb(first);
        }
        Master& m = masters[chosen];
        last = chosen;
        // Arbitration is hidden behind the previous tenure when REQ# came early enough.
        const uint64_t address = std::max(bus_free, m.request_clock + c.arbitration_clocks);
        m.absorb(address);
        PciTenure tenure;
        tenure.address_clock = address;
        const uint64_t data_start = address + c.address_phase_clocks;
        // A target that cannot give the first data within 16 clocks latches the
        // request (a delayed transaction), retries, and has the data later.
        uint32_t latency = m.latency;
        if (m.latency > kPciMaxInitialLatencyClocks) {
            if (m.ready_clock == kNever) m.ready_clock = data_start + m.latency;
            if (m.ready_clock > data_start + kPciMaxInitialLatencyClocks) {
                tenure.retried = true;
                tenure.end_clock = data_start + kPciMaxInitialLatencyClocks;
                bus_free = tenure.end_clock + c.turnaround_clocks;
                m.request_clock = bus_free;  // the master re-arbitrates
                if (chosen == 0) outcome.tenures.push_back(tenure);
                continue;
            }
            latency = static_cast<uint32_t>(std::max<uint64_t>(1, m.ready_clock - data_start));
            m.ready_clock = kNever;
        }
        uint64_t phases = std::min(m.pending_phases, m.burst_phases);
        auto end_of = [&](uint64_t n) { return data_start + latency + n + (n - 1) * c.wait_states; };
        // Another master's REQ# makes the arbiter remove GNT#; the tenure then
        // ends when the latency timer (counting from FRAME#) has expired too.
        uint64_t gnt_removed = kNever;
        for (std::size_t k = 0; k < masters.size(); ++k) {
            if (k == chosen) continue;
            const uint64_t wants = masters[k].wants_bus();
            if (wants != kNever) gnt_removed = std::min(gnt_removed, std::max(address + 1, wants + c.arbitration_clocks));
        }
        if (gnt_removed < end_of(phases)) {
            const uint64_t cut = std::max(gnt_removed, address + c.latency_timer_clocks);
            const uint64_t room = cut > data_start + latency ? (cut - data_start - latency) / (1 + c.wait_states) : 0;
            const uint64_t allowed = std::max<uint64_t>(1, room);
            if (allowed < phases) {
                phases = allowed;
                tenure.cut_by_timer = true;
            }
        }
        tenure.data_phases = phases;
        tenure.end_clock = end_of(phases);
        bus_free = tenure.end_clock + c.turnaround_clocks;
        m.pending_phases -= phases;
        m.request_clock = bus_free;  // a master with more to move asks again once off the bus
        if (chosen == 0) outcome.tenures.push_back(tenure);
    }
    outcome.done_clock = bus_free;
    return outcome;
}

PciTransactionTiming::PciTransactionTiming(const PciConfig& config, const BusLoad& load)
    : formula_(config), bus_(config, load.active() ? std::vector<BusLoad>{load} : std::vector<BusLoad>{}), load_(load) {}

std::string PciTransactionTiming::describe() const {
    std::ostringstream s;
    s << "PCI " << bus_.config().width_bits << "-bit/" << std::setprecision(3) << bus_.config().clock_mhz
      << " MHz, transaction level";
    if (load_.active()) s << ", background " << load_.bytes_per_s / 1e6 << " MB/s";
    return s.str();
}

double PciTransactionTiming::mean_ns(const PciTransfer& transfer) const {
    const int key_kind = static_cast<int>(transfer.kind) * 2 + (transfer.direction == Direction::kToHost ? 1 : 0);
    const std::pair<uint64_t, int> key{transfer.bytes, key_kind};
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    }
    double ns = 0;
    if (!load_.active()) {
        ns = bus_.run(transfer, 0).clocks() * bus_.clock_ns();
    } else {
        // Start k at k/kStartPhases of a gap into the (warm-up + k)th gap between
        // background bursts: every phase of a periodic load once, and as many
        // different stretches of a random one.
        const double period_clocks = load_.period_ns() / bus_.clock_ns();
        double sum = 0;
        for (int k = 0; k < kStartPhases; ++k) {
            const double gaps = kWarmupPeriods + k * (1.0 + 1.0 / kStartPhases);
            const auto start = static_cast<uint64_t>(std::llround(gaps * period_clocks));
            sum += static_cast<double>(bus_.run(transfer, start).clocks());
        }
        ns = sum / kStartPhases * bus_.clock_ns();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    memo_[key] = ns;
    return ns;
}

double PciTransactionTiming::pio_read_ns() const {
    return bus_.config().host_pio_overhead_ns + mean_ns({PciTransfer::Kind::kPioRead, 4, Direction::kToHost});
}

double PciTransactionTiming::pio_write_ns() const {
    return mean_ns({PciTransfer::Kind::kPioWrite, 4, Direction::kToBoard});
}

double PciTransactionTiming::dma_ns(uint64_t bytes, Direction direction) const {
    if (bytes == 0) return 0.0;
    // As in the formula, the bridge's FIFOs decouple the buses: the slower one sets the pace.
    const double local = static_cast<double>(bytes) / bus_.config().local_bus.bytes_per_ns();
    return std::max(mean_ns({PciTransfer::Kind::kDma, bytes, direction}), local);
}

uint64_t PciTransactionTiming::dma_transaction_bytes(Direction direction) const {
    return formula_.dma_transaction_bytes(direction);
}

}  // namespace cdvp
