// cdvp's study library from a program of one's own: runs on the paper's
// board for a few scene sizes with their mean frame time by phase (each a
// RunSpec: the run layer's typed description of a run), a refused run as
// RunFailed, one at the analytic level in this process, and a small sweep
// over m into a temporary directory.
//
//   study_api [OBJECTS...]   (default: 100 200 400)
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "sw/run/run_arguments.h"
#include "sw/study/study_run.h"
#include "sw/study/sweep.h"

namespace {

// The paper's board on its bouncing spheres, `frames` frames of `objects` each.
cdvp::RunSpec paper_board(const std::string& objects, const std::string& frames) {
    cdvp::RunSpec spec;
    spec.settings.board = "adm-xrc-ii";
    spec.frames = cdvp::SceneFrames{"spheres"};
    cdvp::set_input(spec, "scene.objects", objects, true);
    cdvp::set_input(spec, "scene.frames", frames, true);
    return spec;
}

void print_phases(const std::string& objects) {
    cdvp::RunRequest request;
    request.spec = paper_board(objects, "4");
    request.cdvp_binary = CDVP_EXECUTABLE;
    const cdvp::RunResult run = cdvp::run_configuration(request);
    std::printf("N=%-4s %llu frames, %llu pairs; mean us a frame:", objects.c_str(),
                static_cast<unsigned long long>(run.summary.frames), static_cast<unsigned long long>(run.summary.pairs));
    for (std::size_t phase = 0; phase < cdvp::ReportSummary::kPhases; ++phase) {
        std::string key = cdvp::ReportSummary::kPhaseKeys[phase];
        std::printf(" %s %.1f", key.substr(0, key.size() - 3).c_str(), run.summary.mean_phase_ns[phase] / 1e3);
    }
    std::printf("\n");
}

// A bad setting is the run's refusal, with its exit status and message.
int show_refused_run() {
    cdvp::RunRequest request;
    request.spec = paper_board("100", "1");
    request.spec.settings.overrides = {"board.m=99"};
    request.cdvp_binary = CDVP_EXECUTABLE;
    try {
        cdvp::run_configuration(request);
    } catch (const cdvp::RunFailed& e) {
        std::printf("refused: status %d: %s\n", e.status(), e.what());
        return e.status();
    }
    std::printf("refused: NOT REFUSED\n");
    return 0;
}

// The analytic level elaborates no SystemC kernel: it runs in this process.
void print_analytic_run() {
    cdvp::RunRequest request;
    request.spec = paper_board("500", "3");
    cdvp::set_input(request.spec, "run.fidelity", "analytic", true);
    request.in_process = true;
    const cdvp::RunResult run = cdvp::run_configuration(request);
    std::printf("analytic, in this process: %llu frames, %.1f us a frame\n",
                static_cast<unsigned long long>(run.summary.frames), run.summary.mean_phase_ns.back() / 1e3);
}

std::size_t run_small_sweep(const std::string& out_dir) {
    cdvp::SweepSpec spec;
    cdvp::Axis m{"m", {"4", "8"}};
    m.key = "board.m";  // what the axis sets, given typed as cdvp run's --m gives it
    m.flag = "m";
    spec.axes = {m};
    spec.run = paper_board("100", "2");
    // The preset the points read, digested into the sweep's manifest.
    spec.inputs = {{"--board", "adm-xrc-ii", std::string(CDVP_BOARDS_DIR) + "/adm-xrc-ii.json"}};
    spec.out_dir = out_dir;
    spec.jobs = 2;
    spec.quiet = true;
    spec.plots = false;
    spec.program = "study_api";
    spec.cdvp_binary = CDVP_EXECUTABLE;
    const cdvp::SweepOutcome outcome = cdvp::run_sweep(spec);
    std::printf("sweep over m=4,8: status %d, %zu rows (%zu ok, %zu refused, %zu faulted) in %s/sweep.csv\n",
                outcome.status, outcome.points, outcome.ok, outcome.refused, outcome.faulted, out_dir.c_str());
    return outcome.status == 0 ? outcome.points : 0;
}

}  // namespace

int main(int argc, char* argv[]) {
    std::vector<std::string> sizes(argv + 1, argv + argc);
    if (sizes.empty()) sizes = {"100", "200", "400"};
    try {
        for (const std::string& objects : sizes) print_phases(objects);
        if (show_refused_run() != 2) return 1;
        print_analytic_run();
        std::string dir = (std::filesystem::temp_directory_path() / "study_api.XXXXXX").string();
        if (mkdtemp(dir.data()) == nullptr) return 1;
        const std::size_t rows = run_small_sweep(dir + "/sweep");
        std::filesystem::remove_all(dir);
        return rows == 2 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "study_api: %s\n", e.what());
        return 1;
    }
}
