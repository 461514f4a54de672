// What a sweep's list costs before any point runs: a comma list of N values
// whose last repeats an earlier one (refused, found by a hash set in one
// pass: first_repeat), and a range of N whole values stepped in integers. Run with
// --benchmark_repetitions=5 --benchmark_report_aggregates_only=true for
// medians; the time per value should stay flat as N grows a hundredfold.
#include <benchmark/benchmark.h>

#include <string>

#include "models/common/user_text.h"
#include "sw/study/sweep_grid.h"

namespace cdvp {
namespace {

void RepeatedValueInACommaList(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::string list;
    for (std::size_t k = 0; k + 1 < n; ++k) list += std::to_string(k) + ",";
    list += "5";
    for (auto _ : state) {
        try {
            expand_list(list, "--set seed");
            state.SkipWithError("the repeated value was accepted");
        } catch (const InputError& e) {
            benchmark::DoNotOptimize(e.what());
        }
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * n));
}
BENCHMARK(RepeatedValueInACommaList)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);

void WholeRange(benchmark::State& state) {
    const auto n = static_cast<uint64_t>(state.range(0));
    const std::string list = "999999999999:" + std::to_string(999999999999ull + n - 1) + ":+1";
    for (auto _ : state) benchmark::DoNotOptimize(expand_list(list, "--set seed").size());
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * n));
}
BENCHMARK(WholeRange)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cdvp

BENCHMARK_MAIN();
