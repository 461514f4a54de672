// Scenes for the oracle test, in double precision as users give them, each
// from a fixed seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sw/scene/scene.h"

namespace cdvp::oracle {

// Corners uniform in [0, extent)^3, sides uniform in [0, size). With
// float_exact every bound is a float, so conversion cannot widen a box.
std::vector<Box> random_scene(std::size_t n, double extent, double size, bool float_exact, uint32_t seed);

// 'clusters' normal clouds (sigma 'spread') at random centres in [0, 1000)^3.
std::vector<Box> clustered_scene(std::size_t n, std::size_t clusters, double spread, double size, uint32_t seed);

// random_scene shifted by 'offset' on every axis, where float32 spacing is
// coarse (1 at 1e7, 8 at 1e8): many gaps smaller than a float ulp.
std::vector<Box> offset_scene(std::size_t n, double offset, double extent, double size, uint32_t seed);

// k^3 unit cubes on the integer grid, in shuffled order: each touches its
// 26 neighbours on a face, an edge or a corner and overlaps nothing else.
std::vector<Box> touching_grid(std::size_t k);
// Pairs in touching_grid(k): ((3k-2)^3 - k^3) / 2.
std::size_t touching_grid_pairs(std::size_t k);

// kDegenerateFiller random boxes, then 63 special ones (in the order the
// test relies on, see degenerate_scene in the .cpp): zero-width boxes
// (points, flat plates), identical copies, touching faces at -0/+0 and at
// denormals, sub-ulp gaps, infinite slabs and a half-space, bounds beyond
// float range (1e39, 1e300) and at DBL_MAX.
constexpr std::size_t kDegenerateFiller = 1500;
std::vector<Box> degenerate_scene(uint32_t seed);

}  // namespace cdvp::oracle
