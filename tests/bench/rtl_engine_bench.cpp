// Board cycles per second of the rtl engine (the whole-board RTL under
// Verilator) beside the clocked engine, on the paper's board at m = 1, 8 and
// 24 with 500 bouncing spheres (the default scene): one iteration is one
// frame through BoardCore (upload of the boxes that moved, START, the sweep
// to DONE, the pairs read), eight consecutive frames in turn. Each
// benchmark's board_cycles_per_s counter is its speed; the table at the end
// gives the medians over --benchmark_repetitions and the ratio.
//   rtl_engine_bench [--benchmark_repetitions=5] [google benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "models/board/board_core.h"
#include "sw/scene/conversion.h"
#include "sw/scene/spheres.h"
#include "tests/support/core_driver.h"

namespace {

constexpr std::size_t kFrames = 8;
constexpr std::size_t kObjects = 500;

const std::vector<std::vector<cdvp::FloatBox>>& frames() {
    static const std::vector<std::vector<cdvp::FloatBox>> made = [] {
        cdvp::SpheresConfig config;
        config.objects = kObjects;
        cdvp::SpheresScene scene(config);
        std::vector<std::vector<cdvp::FloatBox>> all;
        for (std::size_t f = 0; f < kFrames; ++f) all.push_back(cdvp::to_float_boxes(scene.next().boxes));
        return all;
    }();
    return made;
}

// Per (engine, m): the board cycles per second of each repetition.
std::map<std::pair<int, int>, std::vector<double>>& speeds() {
    static std::map<std::pair<int, int>, std::vector<double>> all;
    return all;
}

void board_frames(benchmark::State& state, cdvp::Fidelity fidelity) {
    cdvp::BoardConfig config;  // the paper's: float32, 2-cycle compare, 512-pair FIFO
    config.m = static_cast<uint32_t>(state.range(0));
    cdvp::BoardCore core(config, 512, fidelity);
    std::size_t f = 0;
    uint64_t cycles = 0;
    for (auto _ : state) {
        const cdvp::testing::CoreRun run = cdvp::testing::run_core(core, frames()[f++ % kFrames]);
        cycles += run.cycles;
        benchmark::DoNotOptimize(run.pairs.data());
    }
    state.counters["board_cycles_per_s"] = benchmark::Counter(static_cast<double>(cycles), benchmark::Counter::kIsRate);
}

void BM_Clocked(benchmark::State& state) { board_frames(state, cdvp::Fidelity::kCycle); }
void BM_Rtl(benchmark::State& state) { board_frames(state, cdvp::Fidelity::kRtl); }
BENCHMARK(BM_Clocked)->Arg(1)->Arg(8)->Arg(24)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Rtl)->Arg(1)->Arg(8)->Arg(24)->Unit(benchmark::kMillisecond)->UseRealTime();

// Collects each run's counter for the closing table.
class TableReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            // Each repetition (the aggregates are computed again below; with
            // --benchmark_report_aggregates_only only the median comes).
            const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
            if (run.run_type != Run::RT_Iteration && !median) continue;
            const std::string name = run.run_name.function_name + "/" + run.run_name.args;
            const int engine = name.rfind("BM_Rtl", 0) == 0 ? 1 : 0;
            const int m = std::stoi(run.run_name.args);
            auto& values = speeds()[{engine, m}];
            if (median) values.assign(1, run.counters.at("board_cycles_per_s"));
            if (!median) values.push_back(run.counters.at("board_cycles_per_s"));
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0 : (n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    TableReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("\nboard cycles per second, %zu spheres, medians over repetitions\n", kObjects);
    std::printf("%4s %14s %14s %10s\n", "m", "clocked", "rtl", "rtl/clocked");
    for (int m : {1, 8, 24}) {
        const double clocked = median(speeds()[{0, m}]), rtl = median(speeds()[{1, m}]);
        if (clocked == 0 || rtl == 0) continue;
        std::printf("%4d %12.2f M %12.2f M %10.3f\n", m, clocked / 1e6, rtl / 1e6, rtl / clocked);
    }
    benchmark::Shutdown();
    return 0;
}
