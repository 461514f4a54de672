// Frames of the bouncing-spheres scene (sw/scene/spheres: 15% of the cube's
// volume filled) as the board stores them, for the benchmarks: each frame's
// float32 boxes and their coordinate words, made once per size and count.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

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

}  // namespace cdvp::bench
