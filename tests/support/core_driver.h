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

// The float32 words of boxes as an engine's box store holds them.
CoordinateStore float32_store(const std::vector<FloatBox>& boxes);

// Boxes with corners uniform in [0, extent)^3 and sizes uniform in [0, size).
std::vector<FloatBox> random_boxes(std::size_t n, float extent, float size, std::mt19937& rng);

// `frames` frames of n random boxes where a fifth of the boxes move by up to
// 0.3 a frame (the same fifth each frame, or the next fifth each frame when
// rotate), and the scene grows by one box at frame 3.
std::vector<std::vector<FloatBox>> moving_frames(uint32_t n, std::mt19937& rng, float extent = 9.0f, int frames = 5,
                                                 bool rotate = false);
// Boxes of `now` that differ from `before` or are new.
uint32_t changed_boxes(const std::vector<FloatBox>& before, const std::vector<FloatBox>& now);

// A register's value; throws for an unmapped offset.
uint32_t read_register(BoardCore& core, uint32_t offset);

}  // namespace cdvp::testing
