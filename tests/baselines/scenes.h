// Box scenes for the baseline tests. Coordinates sit on a grid of 1/8 (exact
// in float32), so boxes often touch exactly: an implementation that treats
// touching as separate, or that misses a pair, disagrees with the reference.
#pragma once

#include <cstdint>
#include <vector>

#include "models/common/aabb.h"

namespace cdvp::test {

using Boxes = std::vector<FloatBox>;

// n boxes, edges 1/8 .. 2, in a cube sized for a few overlaps per box.
Boxes random_boxes(std::size_t n, uint32_t seed);

// frames of n boxes moving by -1/8, 0 or +1/8 per axis and frame, plus two
// scripted boxes (indices n and n + 1) that approach, touch on a face, overlap,
// touch again and part, then touch on an edge and a corner.
std::vector<Boxes> moving_frames(std::size_t n, std::size_t frames, uint32_t seed);

// A cells^3 lattice of cubes [k*step, (k+1)*step], each bound computed as
// float(k) * step so that neighbours share bounds exactly: every cube touches
// its 26 neighbours on faces, edges or corners.
Boxes touching_lattice(int cells, float step);

// A ground slab (x and z unbounded, y in (-inf, 0]), rods with infinite ends,
// and boxes resting on the slab, just above it (one denormal away) and in it.
Boxes infinite_scene();

// n boxes that all contain the origin: every pair overlaps.
Boxes all_overlapping(std::size_t n, uint32_t seed);

// Pairs of boxes in a world of extent ~1000 whose gap is one ulp: far below
// the resolution of a 16-bit quantized sweep and prune, so only an exact test
// separates them. Every other pair touches exactly.
Boxes near_misses(std::size_t pairs);

}  // namespace cdvp::test
