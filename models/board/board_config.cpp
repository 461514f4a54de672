#include "models/board/board_config.h"

#include <cmath>
#include <stdexcept>

#include "models/block_ram/block_ram.h"
#include "models/control_registers/control_registers.h"

namespace cdvp {

uint32_t BoardConfig::pipeline_latency() const {
    return BlockRam::kReadLatencyCycles + compare.latency_cycles + kCollectorLatencyCycles;
}

namespace {
void require(bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
}
}  // namespace

void BoardConfig::validate() const {
    require(m >= 1 && m <= kMaxM, "m must be between 1 and " + std::to_string(kMaxM) +
                                      " (2m-1 lanes, at most 63), got " + std::to_string(m));
    require(std::isfinite(clock_mhz) && clock_mhz >= 1.0 && clock_mhz <= 10000.0,
            "clock must be between 1 and 10000 MHz, got " + std::to_string(clock_mhz));
    require(compare.latency_cycles <= 64,
            "compare latency must be at most 64 cycles, got " + std::to_string(compare.latency_cycles));
    require(collector.fifo_depth >= lanes() && collector.fifo_depth <= (1u << 20),
            "pair FIFO depth must be between 2m-1 = " + std::to_string(lanes()) +
                " (one cycle's hits) and 1048576, got " + std::to_string(collector.fifo_depth));
    require(collector.drain_per_cycle >= 1 && collector.drain_per_cycle <= 64,
            "drain rate must be between 1 and 64 pairs a cycle, got " +
                std::to_string(collector.drain_per_cycle));
    require(collector.buffer_depth >= 1 && collector.buffer_depth <= address_map::kMaxBufferedPairs,
            "pair buffer depth must be between 1 and " + std::to_string(address_map::kMaxBufferedPairs) +
                " pairs, got " + std::to_string(collector.buffer_depth));
}

}  // namespace cdvp
