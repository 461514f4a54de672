// The JSON report of `cdvp run` and its terminal summary.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/board/board_config.h"

namespace cdvp {

struct FrameStats {
    uint64_t frame = 0;
    uint64_t objects = 0;
    uint64_t pairs = 0;
    uint64_t sweep_cycles = 0;  // S(N, m)
    uint64_t compute_cycles = 0;
    uint64_t stall_cycles = 0;
    uint32_t overflow_pauses = 0;
};

struct RunSummary {
    BoardConfig config;
    uint32_t capacity = 0;
    uint32_t block_rams = 0;
    std::string source;
    std::vector<FrameStats> frames;
    double wall_seconds = 0.0;
};

nlohmann::json report_json(const RunSummary& run);
// The short table printed after a run.
void print_summary(std::ostream& out, const RunSummary& run);

}  // namespace cdvp
