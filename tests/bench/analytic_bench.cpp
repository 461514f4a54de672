// Points per second of the analytic frame time: estimate() with the pair
// count given, and with the pairs counted (sort and sweep) on random scenes
// of the density cdvp run's spheres keep (about one pair a box).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "models/pci/bus_timing.h"
#include "platform/driver/analytic_frame.h"

namespace cdvp {
namespace {

// The adm-xrc-ii preset's numbers: PCI 32-bit/33 MHz, 66 MHz board, m = 24.
struct Setup {
    PciTiming bus{PciConfig{}};
    DriverConfig driver;
    AnalyticBoard board;
    Setup() {
        driver.ns_per_box = 25;
        driver.ns_per_pair = 6;
        driver.call_ns = 2000;
        board.period_fs = 15151515;
        board.m = 24;
        board.pipeline_latency = 4;
    }
};

std::vector<FloatBox> scene(std::size_t n, std::mt19937& rng) {
    // Boxes of side up to `size` in a cube holding about one overlap a box.
    const float size = 1.0f, extent = std::cbrt(static_cast<float>(n) * 2.0f) * size;
    std::uniform_real_distribution<float> corner(0.0f, extent), side(0.0f, size);
    std::vector<FloatBox> boxes(n);
    for (FloatBox& b : boxes) {
        for (int a = 0; a < 3; ++a) b.min[a] = corner(rng), b.max[a] = b.min[a] + side(rng);
    }
    return boxes;
}

void BM_EstimateGivenPairs(benchmark::State& state) {
    Setup setup;
    const AnalyticFrame analytic(setup.driver, setup.bus, setup.board);
    const auto n = static_cast<uint32_t>(state.range(0));
    uint64_t pairs = n;
    for (auto _ : state) {
        benchmark::DoNotOptimize(analytic.estimate(n, pairs).total_ns);
        pairs = pairs * 2862933555777941757ull % (4ull * n + 1);  // a different point each time
    }
    state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EstimateGivenPairs)->Arg(1000)->Arg(10000);

void BM_EstimateCountingPairs(benchmark::State& state) {
    Setup setup;
    AnalyticFrame analytic(setup.driver, setup.bus, setup.board);
    std::mt19937 rng(5);
    const std::vector<FloatBox> boxes = scene(static_cast<std::size_t>(state.range(0)), rng);
    PairCounter counter;
    state.counters["pairs"] = static_cast<double>(counter.count(boxes));
    for (auto _ : state) benchmark::DoNotOptimize(analytic.estimate(boxes).total_ns);
    state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EstimateCountingPairs)->Arg(1000)->Arg(10000);

}  // namespace
}  // namespace cdvp

BENCHMARK_MAIN();
