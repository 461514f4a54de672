#include "tests/baselines/scenes.h"

#include <cmath>
#include <limits>
#include <random>

namespace cdvp::test {

namespace {

constexpr float kGrid = 0.125f;
constexpr float kInf = std::numeric_limits<float>::infinity();

FloatBox make_box(float x0, float y0, float z0, float x1, float y1, float z1) {
    return FloatBox{{x0, y0, z0}, {x1, y1, z1}};
}

// A multiple of kGrid in [lo, hi] steps.
float grid_value(std::mt19937& rng, int lo, int hi) {
    return static_cast<float>(std::uniform_int_distribution<int>(lo, hi)(rng)) * kGrid;
}

// The scripted box's x offset from touching its partner, frame by frame:
// apart, touching, overlapping, touching, apart, repeating.
constexpr float kScript[] = {1.0f, 0.5f, 0.0f, -0.25f, -0.5f, -0.25f, 0.0f, 0.125f, 0.0f, 2.0f};

}  // namespace

Boxes random_boxes(std::size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    // Side ~ 2.5 n^(1/3) keeps the pair count near n.
    const int side = static_cast<int>(2.5 * std::cbrt(static_cast<double>(n)) / kGrid) + 8;
    Boxes boxes(n);
    for (FloatBox& box : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = grid_value(rng, 0, side);
            box.max[axis] = box.min[axis] + grid_value(rng, 1, 16);
        }
    }
    return boxes;
}

std::vector<Boxes> moving_frames(std::size_t n, std::size_t frames, uint32_t seed) {
    std::mt19937 rng(seed);
    Boxes boxes = random_boxes(n, seed);
    std::vector<int> velocity(3 * n);
    for (int& v : velocity) v = std::uniform_int_distribution<int>(-1, 1)(rng);
    std::vector<Boxes> out;
    for (std::size_t f = 0; f < frames; ++f) {
        Boxes frame = boxes;
        // Scripted pair far from the random boxes; the y/z offsets switch the
        // contact from a face to an edge (y touches) to a corner (y and z touch).
        const float dx = kScript[f % std::size(kScript)];
        const float dyz = (f / std::size(kScript)) % 3 >= 1 ? 1.0f : 0.0f;
        const float dz = (f / std::size(kScript)) % 3 == 2 ? 1.0f : 0.0f;
        frame.push_back(make_box(-100, -100, -100, -99, -99, -99));
        frame.push_back(make_box(-99 + dx, -100 + dyz, -100 + dz, -98 + dx, -99 + dyz, -99 + dz));
        out.push_back(std::move(frame));
        for (std::size_t i = 0; i < n; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                const float step = static_cast<float>(velocity[3 * i + axis]) * kGrid;
                boxes[i].min[axis] += step;
                boxes[i].max[axis] += step;
            }
        }
    }
    return out;
}

Boxes touching_lattice(int cells, float step) {
    Boxes boxes;
    for (int x = 0; x < cells; ++x) {
        for (int y = 0; y < cells; ++y) {
            for (int z = 0; z < cells; ++z) {
                auto at = [step](int k) { return static_cast<float>(k) * step; };
                boxes.push_back(make_box(at(x), at(y), at(z), at(x + 1), at(y + 1), at(z + 1)));
            }
        }
    }
    return boxes;
}

Boxes infinite_scene() {
    const float above = std::nextafter(0.0f, 1.0f);  // the smallest denormal
    return {
        make_box(-kInf, -kInf, -kInf, kInf, 0, kInf),   // 0: ground slab
        make_box(0, 0, 0, 1, 1, 1),                     // 1: rests on the slab
        make_box(5, above, 5, 6, 1, 6),                 // 2: one denormal above it
        make_box(-3, -2, -3, -2, -1, -2),               // 3: inside the slab
        make_box(-kInf, 0.5f, 0.25f, kInf, 0.75f, 0.5f),  // 4: rod along x through 1
        make_box(5.5f, -kInf, 5.5f, 5.75f, above, 5.75f),  // 5: rod from below, tip touches 2
        make_box(1, 1, 1, kInf, kInf, kInf),            // 6: corner touches 1
        make_box(-kInf, -kInf, -kInf, kInf, kInf, kInf),  // 7: everything
        make_box(1e30f, 1e30f, 1e30f, 2e30f, 2e30f, 2e30f),  // 8: far out, inside 6 and 7
    };
}

Boxes all_overlapping(std::size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> extent(0.0f, 3.0f);
    Boxes boxes(n);
    for (FloatBox& box : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            box.min[axis] = -extent(rng);
            box.max[axis] = extent(rng);
        }
    }
    return boxes;
}

Boxes near_misses(std::size_t pairs) {
    Boxes boxes;
    for (std::size_t k = 0; k < pairs; ++k) {
        const float x = 1000.0f * static_cast<float>(k) / static_cast<float>(pairs);
        const float mid = x + 0.5f;
        boxes.push_back(make_box(x, 0, 0, mid, 1, 1));
        if (k % 2 == 0) {
            boxes.push_back(make_box(std::nextafter(mid, kInf), 0, 0, x + 1, 1, 1));
        } else {
            boxes.push_back(make_box(mid, 0, 0, x + 1, 1, 1));
        }
    }
    return boxes;
}

}  // namespace cdvp::test
