// Time per frame of each software broad phase on boxes moving coherently, the
// setting incremental methods are built for. One iteration is one frame; the
// frames play forwards then backwards so the motion never jumps.
//   baselines_bench [google benchmark flags]
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "sw/baselines/broad_phase.h"
#include "tests/bench/moving_cubes.h"

namespace {

using cdvp::bench::frames;
using cdvp::bench::Frames;

void BM_Frame(benchmark::State& state, const std::string& name) {
    const Frames& scene = frames(static_cast<std::size_t>(state.range(0)));
    auto phase = cdvp::make_broad_phase(name);
    cdvp::PairList pairs;
    phase->find_pairs(scene[0], pairs);  // build outside the timing: steady state only
    std::size_t step = 1, total_pairs = 0;
    for (auto _ : state) {
        phase->find_pairs(scene[cdvp::bench::frame_at(step++)], pairs);
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
// On its threads the call's wall time is what counts (threads_bench: its scaling).
BENCHMARK_CAPTURE(BM_Frame, sap_mt, std::string("sap_mt"))->Arg(500)->Arg(2000)->UseRealTime()->Unit(benchmark::kMicrosecond);
// The libraries' broad phases (FCL's managers, ODE's spaces) at 500 and
// 10,000 boxes, with Bullet's two at 10,000 beside them.
BENCHMARK_CAPTURE(BM_Frame, sap, std::string("sap"))->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, dbvt, std::string("dbvt"))->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, fcl_tree, std::string("fcl_tree"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, fcl_sap, std::string("fcl_sap"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, fcl_interval, std::string("fcl_interval"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, fcl_hash, std::string("fcl_hash"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, ode_hash, std::string("ode_hash"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, ode_quadtree, std::string("ode_quadtree"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Frame, ode_sap, std::string("ode_sap"))->Arg(500)->Arg(10000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
