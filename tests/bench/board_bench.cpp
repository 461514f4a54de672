// Speed of the cycle-level board against a scalar brute force over the same
// boxes, measured side by side in one run. The ratio is printed at the end.
//   board_bench [--vcd] [google benchmark flags]
// --vcd traces the board's waveforms (to a temporary file) to show the cost
// of tracing; a process elaborates once, so tracing on and off are two runs.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <systemc>

#include "platform/kernel.h"
#include "platform/virtual_board.h"
#include "sw/baselines/brute_force.h"
#include "sw/scene/conversion.h"
#include "sw/scene/spheres.h"
#include "sw/scene/trace_csv.h"

namespace {

constexpr std::size_t kObjects = 2000;
constexpr uint32_t kM = 8;
bool g_trace = false;
std::string g_vcd_base;

const std::vector<cdvp::FloatBox>& scene() {
    static const std::vector<cdvp::FloatBox> boxes = [] {
        cdvp::SpheresConfig config;
        config.objects = kObjects;
        config.seed = 7;
        cdvp::SpheresScene spheres(config);
        return cdvp::to_float_boxes(spheres.next().boxes);
    }();
    return boxes;
}

void BM_ScalarBruteForce(benchmark::State& state) {
    cdvp::PairList pairs;
    for (auto _ : state) {
        benchmark::DoNotOptimize(cdvp::brute_force_pairs(scene(), pairs));
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
}

void BM_BoardFrame(benchmark::State& state) {
    cdvp::BoardConfig config;
    config.m = kM;
    static cdvp::VirtualBoard platform("platform", config, kObjects, g_trace ? g_vcd_base : "");
    std::size_t pairs = 0;
    uint64_t cycles = 0;
    for (auto _ : state) {
        const cdvp::FrameResult& result = platform.run_frame(scene());
        pairs = result.pairs.size();
        cycles = result.phases.compute_cycles;
    }
    state.counters["pairs"] = static_cast<double>(pairs);
    state.counters["cycles"] = static_cast<double>(cycles);
    state.counters["board_cycles/s"] =
        benchmark::Counter(static_cast<double>(cycles) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate);
}

// Parsing a 100,000-row trace (100 frames of 1000 spheres).
void BM_ParseTrace(benchmark::State& state) {
    cdvp::SpheresConfig config;
    config.objects = 1000;
    cdvp::SpheresScene spheres(config);
    std::vector<cdvp::Frame> frames;
    for (int k = 0; k < 100; ++k) frames.push_back(spheres.next());
    std::ostringstream out;
    cdvp::write_trace_csv(out, frames);
    const std::string text = out.str();
    for (auto _ : state) {
        std::istringstream in(text);
        benchmark::DoNotOptimize(cdvp::parse_trace_csv(in, "bench.csv").size());
    }
    state.counters["rows/s"] = benchmark::Counter(1e5 * static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}

BENCHMARK(BM_ParseTrace)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScalarBruteForce)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoardFrame)->Unit(benchmark::kMillisecond);

// Console output plus the per-iteration times, to print the ratio.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    RatioReporter() : ConsoleReporter(isatty(1) ? OO_ColorTabular : OO_Tabular) {}
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.run_type == Run::RT_Iteration && run.iterations > 0) {
                seconds_[run.benchmark_name()] = run.real_accumulated_time / static_cast<double>(run.iterations);
            }
        }
    }
    double seconds(const std::string& name) const {
        auto it = seconds_.find(name);
        return it == seconds_.end() ? 0.0 : it->second;
    }

private:
    std::map<std::string, double> seconds_;
};

}  // namespace

int sc_main(int argc, char** argv) {
    cdvp::configure_kernel();
    std::vector<char*> args;
    for (int k = 0; k < argc; ++k) {
        if (std::strcmp(argv[k], "--vcd") == 0) g_trace = true;
        else args.push_back(argv[k]);
    }
    char dir_template[] = "/tmp/cdvp-bench-XXXXXX";
    if (g_trace) {
        if (mkdtemp(dir_template) == nullptr) return 1;
        g_vcd_base = std::string(dir_template) + "/waves";
    }
    int count = static_cast<int>(args.size());
    benchmark::Initialize(&count, args.data());
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const double board = reporter.seconds("BM_BoardFrame");
    const double brute = reporter.seconds("BM_ScalarBruteForce");
    if (board > 0 && brute > 0) {
        std::printf("board frame / scalar brute force (N=%zu, m=%u, tracing %s): %.2fx\n", kObjects, kM,
                    g_trace ? "on" : "off", board / brute);
    }
    if (g_trace) {
        std::remove((g_vcd_base + ".vcd").c_str());
        rmdir(dir_template);
    }
    return 0;
}

// The kernel banner is not part of the benchmark's output.
int main(int argc, char** argv) {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    return sc_core::sc_elab_and_sim(argc, argv);
}
