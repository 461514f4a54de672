// The formula's error against the transaction level, phase by phase of a
// frame, for both shipped buses, three sizes and four background loads.
//
//   build/tests/bus_model_bench [--direction to_host|to_board] [--arrivals periodic|random]
//
// Prints a Markdown table (docs/bus_models.md holds one). The buses are read
// from platform/boards/adm-xrc-ii.json and pcie-gen3-x8.json.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/pci/pci_transaction_bus.h"
#include "models/pci/pcie_tlp_link.h"

namespace cdvp {
namespace {

nlohmann::json bus_section(const std::string& preset) {
    std::ifstream in(std::string(CDVP_SOURCE_DIR) + "/platform/boards/" + preset + ".json");
    return nlohmann::json::parse(in)["bus"];
}
template <class T>
void read(const nlohmann::json& bus, const char* key, T& field) {
    if (bus.contains(key)) field = bus[key]["value"].get<T>();
}

PciConfig pci_of(const nlohmann::json& b) {
    PciConfig c;
    read(b, "width_bits", c.width_bits), read(b, "clock_mhz", c.clock_mhz);
    read(b, "arbitration_clocks", c.arbitration_clocks), read(b, "address_phase_clocks", c.address_phase_clocks);
    read(b, "board_read_latency_clocks", c.board_read_latency_clocks);
    read(b, "board_write_latency_clocks", c.board_write_latency_clocks);
    read(b, "host_read_latency_clocks", c.host_read_latency_clocks);
    read(b, "host_write_latency_clocks", c.host_write_latency_clocks);
    read(b, "wait_states", c.wait_states), read(b, "turnaround_clocks", c.turnaround_clocks);
    read(b, "latency_timer_clocks", c.latency_timer_clocks);
    read(b, "dma_read_burst_bytes", c.dma_read_burst_bytes), read(b, "dma_write_burst_bytes", c.dma_write_burst_bytes);
    read(b, "host_pio_overhead_ns", c.host_pio_overhead_ns), read(b, "interrupt_ns", c.interrupt_ns);
    read(b, "local_bus_width_bits", c.local_bus.width_bits), read(b, "local_bus_clock_mhz", c.local_bus.clock_mhz);
    return c;
}

PcieConfig pcie_of(const nlohmann::json& b) {
    PcieConfig c;
    read(b, "gigatransfers_per_s", c.gigatransfers_per_s), read(b, "lanes", c.lanes);
    read(b, "encoding_efficiency", c.encoding_efficiency), read(b, "max_payload_bytes", c.max_payload_bytes);
    read(b, "max_read_request_bytes", c.max_read_request_bytes), read(b, "tlp_overhead_bytes", c.tlp_overhead_bytes);
    read(b, "read_round_trip_ns", c.read_round_trip_ns), read(b, "posted_write_ns", c.posted_write_ns);
    read(b, "interrupt_ns", c.interrupt_ns);
    read(b, "local_bus_width_bits", c.local_bus.width_bits), read(b, "local_bus_clock_mhz", c.local_bus.clock_mhz);
    return c;
}

struct Phase {
    const char* name;
    bool sized;  // depends on N
    std::function<double(const BusTiming&, uint64_t n)> ns;
};

// Pairs a frame of N boxes reads back: cdvp run's spheres keep about 1.23 a box (616 at 500).
uint64_t pairs_of(uint64_t n) { return (n * 616 + 250) / 500; }

const std::vector<Phase>& phases() {
    static const std::vector<Phase> all = {
        {"upload", true,
         [](const BusTiming& b, uint64_t n) {
             return 6 * (b.dma_ns(4 * n, Direction::kToBoard) + b.dma_ns(24, Direction::kToBoard));
         }},
        {"read-back", true, [](const BusTiming& b, uint64_t n) { return b.dma_ns(8 * pairs_of(n), Direction::kToHost); }},
        {"PIO read", false, [](const BusTiming& b, uint64_t) { return b.pio_read_ns(); }},
        {"PIO write", false, [](const BusTiming& b, uint64_t) { return b.pio_write_ns(); }},
        {"interrupt", false, [](const BusTiming& b, uint64_t) { return b.interrupt_ns(); }},
    };
    return all;
}

void table(const char* board, const BusTiming& formula, const std::function<std::unique_ptr<BusTiming>(double)>& detailed) {
    const double loads[] = {0.0, 0.1, 0.3, 0.6};
    std::vector<std::unique_ptr<BusTiming>> levels;
    for (const double load : loads) levels.push_back(detailed(load));
    for (const Phase& phase : phases()) {
        for (const uint64_t n : {64ull, 500ull, 4000ull}) {
            if (!phase.sized && n != 64) continue;
            const double f = phase.ns(formula, n);
            std::printf("| %s | %s | %s |", board, phase.name, phase.sized ? std::to_string(n).c_str() : "-");
            std::printf(" %.0f |", f);
            for (const auto& level : levels) {
                const double t = phase.ns(*level, n);
                std::printf(" %.0f (%+.1f%%) |", t, 100.0 * (f - t) / t);
            }
            std::printf("\n");
        }
    }
}

}  // namespace
}  // namespace cdvp

int main(int argc, char** argv) {
    using namespace cdvp;
    BusLoad base;
    for (int k = 1; k + 1 < argc; k += 2) {
        if (std::strcmp(argv[k], "--direction") == 0) base.direction = std::strcmp(argv[k + 1], "to_board") == 0 ? Direction::kToBoard : Direction::kToHost;
        if (std::strcmp(argv[k], "--arrivals") == 0) base.arrivals = std::strcmp(argv[k + 1], "random") == 0 ? LoadArrivals::kRandom : LoadArrivals::kPeriodic;
    }
    std::printf("Background: one master, %u-byte bursts, %s, %s arrivals; error = (formula - transaction) / transaction.\n\n",
                base.burst_bytes, base.direction == Direction::kToHost ? "to_host" : "to_board",
                base.arrivals == LoadArrivals::kPeriodic ? "periodic" : "random");
    std::printf("| board | phase | N | formula ns | transaction ns, load 0 | 10%% | 30%% | 60%% |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
    const PciConfig pci = pci_of(bus_section("adm-xrc-ii"));
    const double pci_peak = pci.width_bits / 8.0 * pci.clock_mhz * 1e6;
    table("adm-xrc-ii", PciTiming(pci), [&](double load) {
        BusLoad l = base;
        l.bytes_per_s = load * pci_peak;
        return std::make_unique<PciTransactionTiming>(pci, l);
    });
    const PcieConfig pcie = pcie_of(bus_section("pcie-gen3-x8"));
    const double pcie_peak = pcie.gigatransfers_per_s * pcie.lanes * pcie.encoding_efficiency / 8.0 * 1e9;
    table("pcie-gen3-x8", PcieTiming(pcie), [&](double load) {
        BusLoad l = base;
        l.bytes_per_s = load * pcie_peak;
        return std::make_unique<PcieTlpTiming>(pcie, PcieLinkConfig{}, l);
    });
    return 0;
}
