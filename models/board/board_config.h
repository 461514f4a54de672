// Configuration of the collision board: one struct per block, gathered here.
#pragma once

#include <cstdint>
#include <string>

#include "models/comparison_unit/comparison_unit.h"
#include "models/pair_collector/pair_collector.h"

namespace cdvp {

struct BoardConfig {
    // Parallelism: 2m-port coordinate memories (m block RAMs each), 2m-1 lanes.
    uint32_t m = 8;
    // Board clock in MHz. Default 66: the ADM-XRC-II's local bus clock tops out
    // at 66 MHz and a Virtex-II -4 float datapath is plausible there (assumption).
    double clock_mhz = 66.0;
    ComparisonUnitConfig compare;
    PairCollectorConfig collector;

    static constexpr uint32_t kMaxM = (ComparisonUnit::kMaxLanes + 1) / 2;  // 32
    // Cycles of the collector stage: the FIFO write to the pair buffer write.
    static constexpr uint32_t kCollectorLatencyCycles = 1;

    uint32_t lanes() const { return 2 * m - 1; }
    // L: block RAM read + compare pipeline + collector stage. A sweep takes
    // S(N,m) + L + stall cycles from start to done.
    uint32_t pipeline_latency() const;
    // Clock period in picoseconds (the simulation's time resolution).
    double period_ps() const { return 1e6 / clock_mhz; }
    // Throws std::invalid_argument with one line "SETTING: expected ..., got ...",
    // SETTING named as in the run report's config.
    void validate() const;
};

}  // namespace cdvp
