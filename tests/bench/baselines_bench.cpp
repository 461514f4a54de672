// Time per frame of each software broad phase on boxes moving coherently, the
// setting incremental methods are built for. One iteration is one frame; the
// frames play forwards then backwards so the motion never jumps.
//   baselines_bench [google benchmark flags]
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"

namespace {

constexpr std::size_t kFrames = 64;
constexpr uint32_t kSeed = 2007;

using Frames = std::vector<std::vector<cdvp::FloatBox>>;

// Cubes of half extent 0.5 .. 1 in a cube of side 2.4 n^(1/3) (about one pair
// per box), drifting up to 0.05 per axis and frame and bouncing off the walls.
Frames make_frames(std::size_t n) {
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

const Frames& frames(std::size_t n) {
    static std::map<std::size_t, Frames> cache;
    auto it = cache.find(n);
    if (it == cache.end()) it = cache.emplace(n, make_frames(n)).first;
    return it->second;
}

void BM_Frame(benchmark::State& state, const std::string& name) {
    const Frames& scene = frames(static_cast<std::size_t>(state.range(0)));
    auto phase = cdvp::make_broad_phase(name);
    cdvp::PairList pairs;
    phase->find_pairs(scene[0], pairs);  // build outside the timing: steady state only
    std::size_t step = 1, total_pairs = 0;
    for (auto _ : state) {
        // 0, 1, .., kFrames-1, kFrames-2, .., 1, 0, 1, ..
        const std::size_t period = 2 * (kFrames - 1);
        const std::size_t phase_step = step++ % period;
        const std::size_t f = phase_step < kFrames ? phase_step : period - phase_step;
        phase->find_pairs(scene[f], pairs);
        total_pairs += pairs.size();
        benchmark::ClobberMemory();
    }
    state.counters["pairs"] = benchmark::Counter(static_cast<double>(total_pairs),
                                                 benchmark::Counter::kAvgIterations);
}

BENCHMARK_CAPTURE(BM_Frame, sap, std::string("sap"))->Arg(500)->Arg(2000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, dbvt, std::string("dbvt"))->Arg(500)->Arg(2000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, brute, std::string("brute"))->Arg(500)->Arg(2000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, soa, std::string("soa"))->Arg(500)->Arg(2000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
