#include "models/pci/bus_timing.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "models/common/integer_math.h"

namespace cdvp {

namespace {
void require(bool ok, const std::string& what, double got) {
    if (!ok) {
        std::ostringstream s;
        s << what << ", got " << got;
        throw std::invalid_argument(s.str());
    }
}
}  // namespace

void PciConfig::validate() const {
    require(width_bits == 32 || width_bits == 64, "pci.width_bits: expected 32 or 64", width_bits);
    require(clock_mhz >= 1 && clock_mhz <= 133, "pci.clock_mhz: expected 1 to 133", clock_mhz);
    require(board_read_latency_clocks <= 16, "pci.board_read_latency_clocks: expected at most 16 (PCI 2.2)",
            board_read_latency_clocks);
    require(host_read_latency_clocks <= 16, "pci.host_read_latency_clocks: expected at most 16 (PCI 2.2)",
            host_read_latency_clocks);
    require(wait_states <= 8, "pci.wait_states: expected at most 8 (PCI 2.2)", wait_states);
    require(dma_read_burst_bytes >= width_bits / 8 && dma_write_burst_bytes >= width_bits / 8,
            "pci.dma_*_burst_bytes: expected at least one data phase", std::min(dma_read_burst_bytes, dma_write_burst_bytes));
    require(latency_timer_clocks > address_phase_clocks + std::max(host_read_latency_clocks, host_write_latency_clocks),
            "pci.latency_timer_clocks: expected more than the address phase and initial latency", latency_timer_clocks);
    require(local_bus.width_bits >= 8 && local_bus.clock_mhz > 0, "local_bus: expected a positive width and clock",
            local_bus.clock_mhz);
}

PciTiming::PciTiming(const PciConfig& config) : config_(config) { config_.validate(); }

std::string PciTiming::describe() const {
    std::ostringstream s;
    s << "PCI " << config_.width_bits << "-bit/" << std::setprecision(3) << config_.clock_mhz << " MHz";
    return s.str();
}

// One transaction: the initiator arbitrates, drives the address, waits for the
// target's initial latency, moves one data phase and releases the bus.
uint64_t PciTiming::single_read_clocks() const {
    return config_.arbitration_clocks + config_.address_phase_clocks + config_.board_read_latency_clocks + 1 +
           config_.turnaround_clocks;
}

uint64_t PciTiming::single_write_clocks() const {
    return config_.arbitration_clocks + config_.address_phase_clocks + config_.board_write_latency_clocks + 1 +
           config_.turnaround_clocks;
}

double PciTiming::pio_read_ns() const { return config_.host_pio_overhead_ns + single_read_clocks() * clock_ns(); }

double PciTiming::pio_write_ns() const { return single_write_clocks() * clock_ns(); }

uint64_t PciTiming::dma_transaction_bytes(Direction direction) const {
    return data_phases_per_tenure(direction) * (config_.width_bits / 8);
}

uint64_t PciTiming::data_phases_per_tenure(Direction direction) const {
    const uint64_t width = config_.width_bits / 8;
    const bool to_board = direction == Direction::kToBoard;  // the bridge reads host memory
    const uint64_t burst = (to_board ? config_.dma_read_burst_bytes : config_.dma_write_burst_bytes) / width;
    const uint64_t latency = to_board ? config_.host_read_latency_clocks : config_.host_write_latency_clocks;
    // The latency timer runs from FRAME#; assume it expires (the host bridge
    // wants the bus back), so the tenure ends when it does.
    const uint64_t timer = (config_.latency_timer_clocks - config_.address_phase_clocks - latency) /
                           (1 + config_.wait_states);
    return std::max<uint64_t>(1, std::min(burst, timer));
}

uint64_t PciTiming::dma_clocks(uint64_t bytes, Direction direction) const {
    if (bytes == 0) return 0;
    const uint64_t phases = ceil_div(bytes, config_.width_bits / 8);
    const uint64_t per_tenure = data_phases_per_tenure(direction);
    const uint64_t tenures = ceil_div(phases, per_tenure);
    const uint64_t latency =
        direction == Direction::kToBoard ? config_.host_read_latency_clocks : config_.host_write_latency_clocks;
    const uint64_t overhead =
        config_.arbitration_clocks + config_.address_phase_clocks + latency + config_.turnaround_clocks;
    // Each data phase after the first of a tenure adds the wait states.
    return tenures * overhead + phases + (phases - tenures) * config_.wait_states;
}

double PciTiming::dma_ns(uint64_t bytes, Direction direction) const {
    // The bridge's FIFOs decouple the two buses: the slower one sets the pace.
    const double pci = dma_clocks(bytes, direction) * clock_ns();
    const double local = static_cast<double>(bytes) / config_.local_bus.bytes_per_ns();
    return std::max(pci, local);
}

void PcieConfig::validate() const {
    require(gigatransfers_per_s > 0 && gigatransfers_per_s <= 64, "pcie.gigatransfers_per_s: expected 0 to 64",
            gigatransfers_per_s);
    require(lanes >= 1 && lanes <= 32, "pcie.lanes: expected 1 to 32", lanes);
    require(max_payload_bytes >= 128 && max_read_request_bytes >= 128,
            "pcie.max_payload_bytes: expected at least 128", std::min(max_payload_bytes, max_read_request_bytes));
    require(encoding_efficiency > 0 && encoding_efficiency <= 1, "pcie.encoding_efficiency: expected (0, 1]",
            encoding_efficiency);
}

PcieTiming::PcieTiming(const PcieConfig& config) : config_(config) { config_.validate(); }

std::string PcieTiming::describe() const {
    std::ostringstream s;
    s << "PCIe " << config_.gigatransfers_per_s << " GT/s x" << config_.lanes;
    return s.str();
}

double PcieTiming::link_bytes_per_ns() const {
    const double raw = config_.gigatransfers_per_s * config_.lanes * config_.encoding_efficiency / 8.0;
    return raw * config_.max_payload_bytes / (config_.max_payload_bytes + config_.tlp_overhead_bytes);
}

// A read request (to the board) or a write's payload (to the host) is one TLP.
uint64_t PcieTiming::dma_transaction_bytes(Direction direction) const {
    return direction == Direction::kToBoard ? config_.max_read_request_bytes : config_.max_payload_bytes;
}

double PcieTiming::dma_ns(uint64_t bytes, Direction direction) const {
    if (bytes == 0) return 0.0;
    // Writes stream; reads pay one request-to-completion round trip before
    // data flows (outstanding requests then keep the link busy).
    const double first = direction == Direction::kToBoard ? config_.read_round_trip_ns : 0.0;
    const double rate = std::min(link_bytes_per_ns(), config_.local_bus.bytes_per_ns());
    return first + static_cast<double>(bytes) / rate;
}

}  // namespace cdvp
