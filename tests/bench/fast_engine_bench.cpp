// Time per frame of the fast engine (pairs and register timeline of a whole
// sweep) beside the all-pairs SoA baseline and the clocked BoardCore, on the
// bouncing-spheres scene (sw/scene/spheres: 15% of the cube's volume filled,
// so about the same pairs per box at every N). One iteration is one frame;
// eight consecutive frames are played in turn. A summary of CPU times per
// frame and the ratios closes the output.
//   fast_engine_bench [google benchmark flags]

#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "models/fast_engine/fast_engine.h"
#include "sw/baselines/soa_broad_phase.h"
#include "tests/bench/cpu_time_reporter.h"
#include "tests/bench/spheres_frames.h"
#include "tests/support/core_driver.h"

namespace {

constexpr std::size_t kFrames = 8;

using cdvp::bench::BenchFrame;
const std::vector<BenchFrame>& frames(std::size_t n) { return cdvp::bench::spheres_frames(n, kFrames); }

// The paper's board: m = 24, other settings at their defaults.
cdvp::BoardConfig paper_board() {
    cdvp::BoardConfig config;
    config.m = 24;
    return config;
}

// The paper's board past its block RAMs, as `board.memory` auto builds it
// on the XC2V6000 at m = 8: boxes in SSRAM, tiles of 512 (docs/tiles.md).
cdvp::BoardConfig tiled_board() {
    cdvp::BoardConfig config;
    config.m = 8;
    config.tiles.boxes = 512;
    return config;
}

void run_engine(benchmark::State& state, const cdvp::BoardConfig& board) {
    const auto& scene = frames(static_cast<std::size_t>(state.range(0)));
    cdvp::FastEngine engine(board);
    cdvp::bench::play_engine_frames(state, engine, scene);
}

void BM_FastEngine(benchmark::State& state) { run_engine(state, paper_board()); }
void BM_FastEngineTiled(benchmark::State& state) { run_engine(state, tiled_board()); }

// The pair search alone.
void BM_FastEnginePairsOnly(benchmark::State& state) {
    const auto& scene = frames(static_cast<std::size_t>(state.range(0)));
    cdvp::PairFinder finder;
    cdvp::PairList pairs;
    std::size_t f = 0;
    for (auto _ : state) {
        const BenchFrame& frame = scene[f++ % kFrames];
        finder.find(static_cast<uint32_t>(frame.boxes.size()), frame.view(), pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
}

// The register timeline alone, from pairs found beforehand.
void BM_FastEngineTimelineOnly(benchmark::State& state) {
    const auto& scene = frames(static_cast<std::size_t>(state.range(0)));
    std::vector<cdvp::PairList> pairs(kFrames);
    cdvp::PairFinder finder;
    for (std::size_t f = 0; f < kFrames; ++f) {
        finder.find(static_cast<uint32_t>(scene[f].boxes.size()), scene[f].view(), pairs[f]);
    }
    cdvp::SweepTimeline timeline(paper_board());
    std::size_t f = 0;
    for (auto _ : state) {
        const std::size_t frame = f++ % kFrames;
        timeline.start(static_cast<uint32_t>(scene[frame].boxes.size()), pairs[frame]);
        while (timeline.phase() == cdvp::SweepState::kPaused) timeline.resume();
        benchmark::DoNotOptimize(timeline.segment_cycles());
    }
}

void BM_SoaBaseline(benchmark::State& state) {
    const auto& scene = frames(static_cast<std::size_t>(state.range(0)));
    cdvp::SoaBroadPhase soa;
    cdvp::PairList pairs;
    std::size_t f = 0, total = 0;
    for (auto _ : state) {
        soa.find_pairs(scene[f++ % kFrames].boxes, pairs);
        total += pairs.size();
    }
    state.counters["pairs"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kAvgIterations);
}

// What the fast engine replaces: BoardCore stepped edge by edge to done.
void BM_ClockedBoardCore(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const auto& scene = frames(n);
    cdvp::BoardCore core(paper_board(), static_cast<uint32_t>(n));
    std::size_t f = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(cdvp::testing::run_core(core, scene[f++ % kFrames].boxes).cycles);
    }
}

BENCHMARK(BM_FastEngine)->Arg(500)->Arg(2000)->Arg(10000)->Arg(65536)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FastEnginePairsOnly)->Arg(500)->Arg(2000)->Arg(10000)->Arg(65536)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FastEngineTimelineOnly)->Arg(500)->Arg(2000)->Arg(10000)->Arg(65536)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SoaBaseline)->Arg(500)->Arg(2000)->Arg(10000)->Arg(65536)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FastEngineTiled)->Arg(2000)->Arg(10000)->Arg(65536)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ClockedBoardCore)->Arg(500)->Arg(2000)->Arg(10000)->Unit(benchmark::kMicrosecond);


}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    cdvp::bench::CpuTimeReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("CPU time per frame, fast engine (pairs + timeline) against:\n");
    for (const char* n : {"500", "2000", "10000", "65536"}) {
        const double fast = reporter.cpu_us(std::string("BM_FastEngine/") + n);
        if (fast <= 0) continue;
        std::printf("  N=%-6s fast engine %10.1f us", n, fast);
        const std::pair<const char*, const char*> others[] = {{"BM_SoaBaseline/", "soa"},
                                                              {"BM_ClockedBoardCore/", "clocked core"}};
        for (const auto& [name, label] : others) {
            const double us = reporter.cpu_us(name + std::string(n));
            if (us > 0) std::printf("   %s %.1f us (%.1fx)", label, us, us / fast);
        }
        std::printf("\n");
    }
    return 0;
}
