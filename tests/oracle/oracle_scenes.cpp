#include "tests/oracle/oracle_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

namespace cdvp::oracle {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Box cube(double x, double y, double z, double side) {
    return Box{{x, y, z}, {x + side, y + side, z + side}};
}

}  // namespace

std::vector<Box> random_scene(std::size_t n, double extent, double size, bool float_exact, uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> corner(0.0, extent), side(0.0, size);
    std::vector<Box> boxes(n);
    for (Box& b : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            b.min[axis] = corner(rng);
            b.max[axis] = b.min[axis] + side(rng);
            if (float_exact) {
                b.min[axis] = static_cast<float>(b.min[axis]);
                b.max[axis] = std::fmax(b.min[axis], static_cast<float>(b.max[axis]));
            }
        }
    }
    return boxes;
}

std::vector<Box> clustered_scene(std::size_t n, std::size_t clusters, double spread, double size, uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> centre(0.0, 1000.0), side(0.0, size);
    std::normal_distribution<double> cloud(0.0, spread);
    std::vector<std::array<double, 3>> centres(clusters);
    for (auto& c : centres) c = {centre(rng), centre(rng), centre(rng)};
    std::vector<Box> boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            boxes[i].min[axis] = centres[i % clusters][axis] + cloud(rng);
            boxes[i].max[axis] = boxes[i].min[axis] + side(rng);
        }
    }
    return boxes;
}

std::vector<Box> offset_scene(std::size_t n, double offset, double extent, double size, uint32_t seed) {
    std::vector<Box> boxes = random_scene(n, extent, size, false, seed);
    for (Box& b : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            b.min[axis] += offset;
            b.max[axis] += offset;
        }
    }
    return boxes;
}

std::vector<Box> touching_grid(std::size_t k) {
    std::vector<Box> boxes;
    for (std::size_t x = 0; x < k; ++x) {
        for (std::size_t y = 0; y < k; ++y) {
            for (std::size_t z = 0; z < k; ++z) boxes.push_back(cube(x, y, z, 1.0));
        }
    }
    // Shuffled, so that each touching face meets the comparators from both
    // sides (in grid order the lower box would always come first).
    std::mt19937_64 rng(k);
    std::shuffle(boxes.begin(), boxes.end(), rng);
    return boxes;
}

std::size_t touching_grid_pairs(std::size_t k) {
    const std::size_t wide = 3 * k - 2;
    return (wide * wide * wide - k * k * k) / 2;
}

std::vector<Box> degenerate_scene(uint32_t seed) {
    const double denormal = std::numeric_limits<double>::denorm_min();
    const double float_denormal = std::numeric_limits<float>::denorm_min();
    std::vector<Box> boxes = random_scene(kDegenerateFiller, 60.0, 3.0, false, seed);
    // Points and flat plates, on and inside other boxes.
    boxes.push_back({{5, 5, 5}, {5, 5, 5}});
    boxes.push_back({{5, 5, 5}, {5, 5, 5}});
    boxes.push_back({{4, 5, 4}, {6, 5, 6}});
    boxes.push_back({{0.1, 0.1, 0.1}, {0.1, 0.1, 0.1}});
    // Identical copies.
    for (int copy = 0; copy < 40; ++copy) boxes.push_back(cube(20.25, 20.5, 20.75, 0.3));
    // Touching at -0 / +0, at a float denormal, and one double denormal apart.
    boxes.push_back({{-1, 70, 0}, {-0.0, 71, 1}});
    boxes.push_back({{0.0, 70, 0}, {1, 71, 1}});
    boxes.push_back({{-1, 72, 0}, {float_denormal, 73, 1}});
    boxes.push_back({{float_denormal, 72, 0}, {1, 73, 1}});
    boxes.push_back({{-1, 74, 0}, {0.0, 75, 1}});
    boxes.push_back({{denormal, 74, 0}, {1, 75, 1}});
    // Sub-ulp gap: 1 + 2^-52 is not a float, its min rounds down to 1.
    boxes.push_back({{0, 76, 0}, {1, 77, 1}});
    boxes.push_back({{1 + std::ldexp(1.0, -52), 76, 0}, {2, 77, 1}});
    // Infinite slabs and a half-space.
    boxes.push_back({{-kInf, -1, -kInf}, {kInf, 0, kInf}});
    boxes.push_back({{-kInf, 30, -kInf}, {kInf, 30, kInf}});
    boxes.push_back({{59, -kInf, -kInf}, {kInf, kInf, kInf}});
    boxes.push_back({{-kInf, -kInf, -kInf}, {-kInf, -kInf, -kInf}});
    boxes.push_back({{kInf, kInf, kInf}, {kInf, kInf, kInf}});
    // Beyond float range: 1e39 and disjoint boxes near 1e300.
    boxes.push_back({{1e39, 1e39, 1e39}, {2e39, 2e39, 2e39}});
    boxes.push_back({{1e300, 1e300, 1e300}, {2e300, 2e300, 2e300}});
    boxes.push_back({{3e300, 3e300, 3e300}, {4e300, 4e300, 4e300}});
    boxes.push_back({{-4e300, -4e300, -4e300}, {-3e300, -3e300, -3e300}});
    // The largest doubles, touching.
    const double top = std::numeric_limits<double>::max();
    boxes.push_back({{top, top, top}, {top, top, top}});
    boxes.push_back({{1e308, 1e308, 1e308}, {top, top, top}});
    return boxes;
}

}  // namespace cdvp::oracle
