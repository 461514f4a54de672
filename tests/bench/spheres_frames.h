// Frames of the bouncing-spheres scene (sw/scene/spheres: 15% of the cube's
// volume filled) as the board stores them, for the benchmarks: each frame's
// float32 boxes and their coordinate words, made once per size and count.
#pragma once

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "models/board_spec/board_engine.h"
#include "models/fast_engine/pair_finder.h"
#include "sw/scene/conversion.h"
#include "sw/scene/spheres.h"

namespace cdvp::bench {

struct BenchFrame {
    std::vector<FloatBox> boxes;
    std::array<std::vector<uint32_t>, kCoordinates> words;
    CoordinateWords view() const {
        CoordinateWords view{};
        for (uint32_t c = 0; c < kCoordinates; ++c) view[c] = words[c].data();
        return view;
    }
};

// `count` consecutive frames of n spheres (seed 1), kept for the process.
inline const std::vector<BenchFrame>& spheres_frames(std::size_t n, std::size_t count) {
    static std::map<std::pair<std::size_t, std::size_t>, std::vector<BenchFrame>> cache;
    auto it = cache.find({n, count});
    if (it != cache.end()) return it->second;
    SpheresConfig config;
    config.objects = n;
    SpheresScene scene(config);
    std::vector<BenchFrame> made(count);
    for (BenchFrame& frame : made) {
        frame.boxes = to_float_boxes(scene.next().boxes);
        for (auto& column : frame.words) column.reserve(n);
        for (const FloatBox& box : frame.boxes) {
            for (uint32_t c = 0; c < kCoordinates; ++c) {
                frame.words[c].push_back(ComparisonUnit::as_bits(c < 3 ? box.min[c] : box.max[c - 3]));
            }
        }
    }
    return cache.emplace(std::make_pair(n, count), std::move(made)).first->second;
}

// Plays `scene`'s frames in turn through a board engine, one frame an
// iteration, and counts its pairs and board cycles a frame.
template <class Engine>
void play_engine_frames(benchmark::State& state, Engine& engine, const std::vector<BenchFrame>& scene) {
    std::size_t f = 0, pairs = 0;
    uint64_t cycles = 0;
    for (auto _ : state) {
        const BenchFrame& frame = scene[f++ % scene.size()];
        engine.start(static_cast<uint32_t>(frame.boxes.size()), frame.view());
        while (engine.phase() == SweepState::kPaused) engine.resume();
        pairs += engine.pairs().size();
        cycles += engine.observe(engine.segment_cycles()).cycles;
    }
    state.counters["pairs"] = benchmark::Counter(static_cast<double>(pairs), benchmark::Counter::kAvgIterations);
    state.counters["board_cycles"] = benchmark::Counter(static_cast<double>(cycles), benchmark::Counter::kAvgIterations);
}

}  // namespace cdvp::bench
