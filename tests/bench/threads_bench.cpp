// The multi-threaded sweep and prune (sap_mt) against its own threads: wall
// time a frame at 1, 2, .. threads up to this machine's cores (and twice
// them, to show what oversubscription costs), on the coherent cubes the
// baselines' benchmark times; then a table of each count's median over the
// repetitions and its speedup over one thread, side by side.
//   threads_bench [--benchmark_repetitions=N] [google benchmark flags]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/worker_pool.h"
#include "tests/bench/moving_cubes.h"

namespace {

void BM_SapThreads(benchmark::State& state) {
    const auto& scene = cdvp::bench::frames(static_cast<std::size_t>(state.range(0)));
    auto phase = cdvp::make_broad_phase("sap_mt", cdvp::BaselineOptions{static_cast<unsigned>(state.range(1))});
    cdvp::PairList pairs;
    phase->find_pairs(scene[0], pairs);
    std::size_t step = 1;
    for (auto _ : state) {
        phase->find_pairs(scene[cdvp::bench::frame_at(step++)], pairs);
        benchmark::ClobberMemory();
    }
}

// Keeps each run's median wall time a frame, by (boxes, threads), beside the console's report.
class MedianCollector : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
            const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
            if (!median && !single) continue;
            // "N:2000/threads:2": the numbers after the colons.
            const std::string& args = run.run_name.args;
            const std::size_t n_at = args.find(':') + 1, slash = args.find('/');
            const unsigned long n = std::stoul(args.substr(n_at, slash - n_at));
            const unsigned long threads = std::stoul(args.substr(args.find(':', slash) + 1));
            medians[n][threads] = run.GetAdjustedRealTime();
        }
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<unsigned long, std::map<unsigned long, double>> medians;  // [N][threads] = us
};

}  // namespace

int main(int argc, char** argv) {
    const unsigned cores = cdvp::machine_threads();
    std::vector<int64_t> threads;
    for (unsigned t = 1; t <= cores; ++t) threads.push_back(t);
    threads.push_back(2 * cores);
    auto* bench = benchmark::RegisterBenchmark("BM_SapThreads", BM_SapThreads);
    bench->ArgsProduct({{2000, 10000, 30000}, threads})->ArgNames({"N", "threads"});
    bench->UseRealTime()->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
    benchmark::Initialize(&argc, argv);
    MedianCollector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    std::printf("\nsap_mt on %u cores: median wall time a frame (us) and speedup over one thread\n", cores);
    std::printf("%8s %8s %12s %9s\n", "N", "threads", "wall_us", "speedup");
    for (const auto& [n, by_threads] : collector.medians) {
        const auto one = by_threads.find(1);
        for (const auto& [t, us] : by_threads) {
            std::printf("%8lu %8lu %12.1f %8.2fx\n", n, t, us, one == by_threads.end() ? 0.0 : one->second / us);
        }
    }
    benchmark::Shutdown();
    return 0;
}
