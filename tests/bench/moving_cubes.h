// Cubes moving coherently, the frames the baselines' benchmarks time: one
// scene per box count, built once and kept.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp::bench {

inline constexpr std::size_t kFrames = 64;
inline constexpr uint32_t kSeed = 2007;

using Frames = std::vector<std::vector<cdvp::FloatBox>>;

// Cubes of half extent 0.5 .. 1 in a cube of side 2.4 n^(1/3) (about one pair
// per box), drifting up to 0.05 per axis and frame and bouncing off the walls.
inline Frames make_frames(std::size_t n) {
    std::mt19937 rng(kSeed);
    const float side = 2.4f * std::cbrt(static_cast<float>(n));
    std::uniform_real_distribution<float> position(0.0f, side);
    std::uniform_real_distribution<float> half(0.5f, 1.0f);
    std::uniform_real_distribution<float> speed(-0.05f, 0.05f);
    std::vector<float> centre(3 * n), extent(n), velocity(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        extent[i] = half(rng);
        for (int axis = 0; axis < 3; ++axis) {
            centre[3 * i + axis] = position(rng);
            velocity[3 * i + axis] = speed(rng);
        }
    }
    Frames frames(kFrames, std::vector<cdvp::FloatBox>(n));
    for (auto& frame : frames) {
        for (std::size_t i = 0; i < n; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                float& c = centre[3 * i + axis];
                float& v = velocity[3 * i + axis];
                if (c + v < 0.0f || c + v > side) v = -v;
                c += v;
                frame[i].min[axis] = c - extent[i];
                frame[i].max[axis] = c + extent[i];
            }
        }
    }
    return frames;
}

inline const Frames& frames(std::size_t n) {
    static std::map<std::size_t, Frames> cache;
    auto it = cache.find(n);
    if (it == cache.end()) it = cache.emplace(n, make_frames(n)).first;
    return it->second;
}

// The frame of iteration `step`: 0, 1, .., kFrames-1, kFrames-2, .., 1, 0, 1, ..
// (forwards then backwards, so the motion never jumps).
inline std::size_t frame_at(std::size_t step) {
    const std::size_t period = 2 * (kFrames - 1);
    const std::size_t phase_step = step % period;
    return phase_step < kFrames ? phase_step : period - phase_step;
}

}  // namespace cdvp::bench
