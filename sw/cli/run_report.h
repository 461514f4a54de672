// The JSON report of `cdvp run` and its terminal summary.
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/board/board_config.h"
#include "sw/driver/board_driver.h"

namespace cdvp {

struct BaselineTime {
    double ns = 0;         // measured natively on this machine
    double scaled_ns = 0;  // ns x the host-speed factor: on the modelled host
};

struct FrameStats {
    uint64_t frame = 0;
    uint64_t objects = 0;
    uint64_t pairs = 0;
    uint64_t sweep_cycles = 0;  // S(N, m)
    FramePhases phases;         // simulated; compute_cycles, stall_cycles, overflow_pauses inside
    std::map<std::string, BaselineTime> baselines;
};

struct RunSummary {
    BoardConfig config;
    uint32_t capacity = 0;
    uint32_t block_rams = 0;
    std::string source;
    std::string board = "ideal";  // preset name
    std::string bus;
    std::string host;
    double host_factor = 1.0;
    bool dma = true;
    bool interrupts = true;
    double quantum_ns = 0.0;
    std::string fidelity = "cycle";
    std::vector<std::string> baseline_names;
    std::vector<std::string> inject;  // fault specs, as parsed
    std::vector<FrameStats> frames;
    double wall_seconds = 0.0;
};

nlohmann::json report_json(const RunSummary& run);
// The short table printed after a run.
void print_summary(std::ostream& out, const RunSummary& run);

}  // namespace cdvp
