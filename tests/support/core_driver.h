// Test support: drive a BoardCore the way the host does, without a kernel,
// and make random scenes.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "models/board/board_core.h"

namespace cdvp::testing {

struct CoreRun {
    PairList pairs;
    uint64_t cycles = 0;
    uint64_t stalls = 0;
    uint32_t pauses = 0;
};

// Loads boxes, starts, steps until done, drains the pair buffer on each pause.
CoreRun run_core(BoardCore& core, const std::vector<FloatBox>& boxes);

// Boxes with corners uniform in [0, extent)^3 and sizes uniform in [0, size).
std::vector<FloatBox> random_boxes(std::size_t n, float extent, float size, std::mt19937& rng);

}  // namespace cdvp::testing
