// Time per frame of the grid board's fast engine (binning, pairs and their
// slots, and the register timeline of the whole sweep) on the
// bouncing-spheres scene (15% of the cube's volume filled, so about the same
// pairs per box at every N), beside the all-pairs board's fast engine. One
// iteration is one frame; three consecutive frames are played in turn.
// Before anything is timed, the grid board's pairs of a 10^6-box frame are
// checked against CGAL's box_self_intersection_d on the same float32 boxes
// (exit 1 on any difference). A summary of CPU times per frame closes the
// output.
//   grid_engine_bench [google benchmark flags]

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "models/fast_engine/fast_engine.h"
#include "models/grid_fast_engine/grid_fast_engine.h"
#include "tests/bench/cpu_time_reporter.h"
#include "tests/bench/spheres_frames.h"
#include "tests/oracle/cgal_oracle.h"

namespace {

constexpr std::size_t kFrames = 3;

using cdvp::bench::BenchFrame;
const std::vector<BenchFrame>& frames(std::size_t n) { return cdvp::bench::spheres_frames(n, kFrames); }

// The PCIe what-if's board (platform/boards/pcie-gen3-x8.json) at m = 8:
// a 2M-pair buffer drained four pairs a cycle, SSRAM 8 cycles from address
// to data; as a grid board, the default grid.
cdvp::BoardConfig pcie_board(cdvp::BoardAlgorithm algorithm) {
    cdvp::BoardConfig config;
    config.m = 8;
    config.algorithm = algorithm;
    config.collector.drain_per_cycle = 4;
    config.collector.buffer_depth = 2097152;
    config.tiles.load_latency_cycles = 8;
    return config;
}

template <class Engine>
void run_engine(benchmark::State& state, cdvp::BoardAlgorithm algorithm) {
    const auto& scene = frames(static_cast<std::size_t>(state.range(0)));
    Engine engine(pcie_board(algorithm));
    cdvp::bench::play_engine_frames(state, engine, scene);
}

void BM_GridFastEngine(benchmark::State& state) {
    run_engine<cdvp::GridFastEngine>(state, cdvp::BoardAlgorithm::kGrid);
    // The grid of the last frame: cells a side, entries a box, boxes a busy cell.
    const BenchFrame& frame = frames(static_cast<std::size_t>(state.range(0)))[0];
    cdvp::GridFastEngine engine(pcie_board(cdvp::BoardAlgorithm::kGrid));
    engine.start(static_cast<uint32_t>(frame.boxes.size()), frame.view());
    const cdvp::GridSweepStats& grid = engine.stats();
    state.counters["dims"] = grid.dims;
    state.counters["entries_a_box"] = static_cast<double>(grid.cell_entries) / static_cast<double>(state.range(0));
    state.counters["boxes_a_busy_cell"] = static_cast<double>(grid.cell_entries) / std::max(1u, grid.busy_cells);
    state.counters["large"] = grid.large_boxes;
}
void BM_AllPairsFastEngine(benchmark::State& state) {
    run_engine<cdvp::FastEngine>(state, cdvp::BoardAlgorithm::kAllPairs);
}

// The grid search's frames played in turn, one an iteration.
void play_search(benchmark::State& state, cdvp::GridSearch& search) {
    const auto& scene = frames(static_cast<std::size_t>(state.range(0)));
    cdvp::PairList pairs;
    std::vector<uint64_t> slots;
    std::size_t f = 0;
    for (auto _ : state) {
        const BenchFrame& frame = scene[f++ % kFrames];
        benchmark::DoNotOptimize(search.run(static_cast<uint32_t>(frame.boxes.size()), frame.view(), pairs, slots));
    }
}

// The binning and the pairs with their slots alone, without the timeline.
void BM_GridSearchOnly(benchmark::State& state) {
    cdvp::GridSearch search(pcie_board(cdvp::BoardAlgorithm::kGrid));
    play_search(state, search);
}

// The grid search when its cell entries run out: an entry memory of half
// an entry a box (a box takes one to eight), so most boxes overflow into the
// large sweep; the second argument streams every box past every large tile as
// the board does (1) or searches those pairs (0, what the engine picks above
// GridSearch::kStreamedLargeBoxes large boxes).
void BM_GridSearchOverflow(benchmark::State& state) {
    cdvp::BoardConfig config = pcie_board(cdvp::BoardAlgorithm::kGrid);
    config.grid.entry_capacity = static_cast<uint64_t>(state.range(0)) / 2;
    cdvp::GridSearch search(config);
    if (state.range(1) != 0) search.set_searched_above(~0u);
    play_search(state, search);
    state.counters["large"] = search.stats().large_boxes;
}

BENCHMARK(BM_GridFastEngine)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridSearchOnly)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AllPairsFastEngine)->Arg(10000)->Arg(30000)->Arg(100000)->Arg(300000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridSearchOverflow)
    ->Args({10000, 1})->Args({30000, 1})
    ->Args({10000, 0})->Args({30000, 0})->Args({100000, 0})->Args({300000, 0})
    ->Unit(benchmark::kMillisecond);

// The grid board's pairs of the first 10^6-box frame against CGAL on the
// same float32 boxes (as doubles, exactly): equal as sets, each pair once.
bool oracle_check(std::size_t n) {
    const BenchFrame& frame = frames(n)[0];
    cdvp::GridFastEngine engine(pcie_board(cdvp::BoardAlgorithm::kGrid));
    engine.start(static_cast<uint32_t>(n), frame.view());
    const cdvp::PairList grid = cdvp::sorted(engine.pairs());
    std::vector<cdvp::Box> boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            boxes[i].min[a] = frame.boxes[i].min[a];
            boxes[i].max[a] = frame.boxes[i].max[a];
        }
    }
    const auto begin = std::chrono::steady_clock::now();
    const cdvp::PairList oracle = cdvp::oracle::cgal_pairs(boxes);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    const bool same = grid == oracle;
    std::printf("oracle: %zu boxes, grid board %zu pairs, CGAL box_self_intersection_d %zu pairs (%.1f s): %s\n", n,
                grid.size(), oracle.size(), seconds, same ? "equal" : "DIFFERENT");
    return same;
}


}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (!oracle_check(1000000)) return 1;
    cdvp::bench::CpuTimeReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("CPU time per frame (the grid board's fast engine: binning, pairs, slots, timeline):\n");
    for (const char* n : {"10000", "100000", "1000000"}) {
        const double grid = reporter.cpu_ms(std::string("BM_GridFastEngine/") + n);
        if (grid <= 0) continue;
        std::printf("  N=%-8s grid %9.2f ms (search alone %.2f ms)", n, grid,
                    reporter.cpu_ms(std::string("BM_GridSearchOnly/") + n));
        const double all_pairs = reporter.cpu_ms(std::string("BM_AllPairsFastEngine/") + n);
        if (all_pairs > 0) std::printf("   all-pairs board's fast engine %.2f ms (%.1fx)", all_pairs, all_pairs / grid);
        std::printf("\n");
    }
    std::printf("CPU time per frame, the cell entries run out (half an entry a box), most boxes large:\n");
    for (const char* n : {"10000", "30000", "100000", "300000"}) {
        const double searched = reporter.cpu_ms(std::string("BM_GridSearchOverflow/") + n + "/0");
        if (searched <= 0) continue;
        std::printf("  N=%-8s searched %9.2f ms", n, searched);
        const double streamed = reporter.cpu_ms(std::string("BM_GridSearchOverflow/") + n + "/1");
        if (streamed > 0) std::printf("   streamed %.2f ms (%.1fx)", streamed, streamed / searched);
        const double all_pairs = reporter.cpu_ms(std::string("BM_AllPairsFastEngine/") + n);
        if (all_pairs > 0) std::printf("   all-pairs board's fast engine %.2f ms (%.2fx)", all_pairs, searched / all_pairs);
        std::printf("\n");
    }
    return 0;
}
