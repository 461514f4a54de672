// A btDiscreteDynamicsWorld step at 3,000 bodies (the boxes scene: 3,000 boxes
// falling onto a ground plane) with the virtual board as its broad phase (fast
// engine) against btDbvtBroadphase and btAxisSweep3, side by side in one run.
// An iteration steps a fresh world through the same 60 frames (built outside
// the timing), so every broad phase is timed over the same stretch of the
// scene. The ratio board / dbvt is printed at the end (the aim: at most 1.2x,
// i.e. the simulator does not dominate the step).
//   bullet_bench [google benchmark flags]
#include <cstdio>
#include <map>
#include <utility>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>
#include <systemc>

#include "platform/kernel.h"
#include "sw/bullet/board_broadphase.h"
#include "sw/bullet/scenes.h"

namespace {

constexpr uint32_t kBodies = 3000;
constexpr int kFrames = 60;
const cdvp::SceneSpec kScene{"boxes", kBodies, 1};

// One board per process, shared by every world the benchmark builds.
cdvp::LazyVirtualBoard& board_link() {
    static cdvp::LazyVirtualBoard link = [] {
        cdvp::PlatformConfig config;
        config.board.m = 8;
        config.fidelity = cdvp::Fidelity::kFast;
        return cdvp::LazyVirtualBoard(config, cdvp::scene_layout(kScene).proxies);
    }();
    return link;
}

void step_scene(benchmark::State& state, cdvp::BroadphaseKind kind) {
    double broadphase_ns = 0, step_ns = 0;
    std::size_t contacts = 0;
    for (auto _ : state) {
        state.PauseTiming();
        auto world = cdvp::make_scene_world(kScene, kind, &board_link());
        state.ResumeTiming();
        for (int frame = 0; frame < kFrames; ++frame) {
            const cdvp::StepTimes times = world->step();
            broadphase_ns += times.broadphase_share_ns();
            step_ns += times.step_ns;
        }
        state.PauseTiming();
        contacts = world->contact_points();
        world.reset();
        state.ResumeTiming();
    }
    const double steps = static_cast<double>(state.iterations()) * kFrames;
    state.counters["broadphase_share"] = broadphase_ns / step_ns;
    state.counters["ms/step"] = step_ns / steps * 1e-6;
    state.counters["contacts"] = static_cast<double>(contacts);
}

void BM_StepDbvt(benchmark::State& state) { step_scene(state, cdvp::BroadphaseKind::kDbvt); }
void BM_StepSap(benchmark::State& state) { step_scene(state, cdvp::BroadphaseKind::kSap); }
void BM_StepBoard(benchmark::State& state) { step_scene(state, cdvp::BroadphaseKind::kBoard); }

BENCHMARK(BM_StepDbvt)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_StepSap)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_StepBoard)->Unit(benchmark::kMillisecond)->Iterations(3);

class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.run_type == Run::RT_Iteration && run.iterations > 0) {
                const auto n = static_cast<double>(run.iterations);
                seconds_[run.benchmark_name()] = {run.real_accumulated_time / n, run.cpu_accumulated_time / n};
            }
        }
    }
    // Wall and CPU seconds an iteration (0, 0 if the benchmark did not run).
    std::pair<double, double> seconds(const std::string& name) const {
        auto it = seconds_.find(name);
        return it == seconds_.end() ? std::pair<double, double>{0, 0} : it->second;
    }

private:
    std::map<std::string, std::pair<double, double>> seconds_;
};

}  // namespace

int sc_main(int argc, char** argv) {
    cdvp::configure_kernel();
    benchmark::Initialize(&argc, argv);
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const auto board = reporter.seconds("BM_StepBoard/iterations:3");
    const auto dbvt = reporter.seconds("BM_StepDbvt/iterations:3");
    // On a shared machine the wall clock also counts other processes' turns:
    // the CPU ratio is the one to trust there.
    if (board.first > 0 && dbvt.first > 0 && dbvt.second > 0) {
        std::printf("world step with the board (fast engine) / with btDbvtBroadphase (%u bodies, %d frames): "
                    "%.2fx wall, %.2fx CPU\n",
                    kBodies, kFrames, board.first / dbvt.first, board.second / dbvt.second);
    }
    return 0;
}

int main(int argc, char** argv) {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    const int status = sc_core::sc_elab_and_sim(argc, argv);
    cdvp::after_kernel_returns();
    return status;
}
