// Points per second of cdvp sweep at the analytic level, its points run in
// the sweep's own process: each grid as a compact record (a row a point) and
// the smaller ones also as a full one (a report a point), alternating in one
// run, medians of --repeat runs (default 3). The grids' points share scenes,
// as a design-space sweep's do: m, clock and bus leave a scene's pairs as
// they are; the first new scene of each point costs its generation and pair
// search. Also the time a point costs past the process's start (a sweep of
// one point).
//
//   ./build/tests/analytic_sweep_bench [--repeat R] [--large]
//   --large adds 10^5 points at N = 1,000 (compact only)
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

double run_sweep(const std::string& grid, const std::string& record, const fs::path& out) {
    fs::remove_all(out);
    const std::string command = std::string("'") + CDVP_BINARY + "' sweep --board adm-xrc-ii --fidelity analytic " + grid +
                                " --frames 1 --warmup 0 --no-plots -q --record " + record + " --out '" + out.string() + "'";
    const auto start = std::chrono::steady_clock::now();
    if (std::system(command.c_str()) != 0) {
        std::fprintf(stderr, "analytic_sweep_bench: failed: %s\n", command.c_str());
        std::exit(1);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

struct Grid {
    const char* label;
    std::string axes;
    double points;
    double scenes;
    bool full;  // also as a full record
};

}  // namespace

int main(int argc, char** argv) {
    int repeat = 3;
    bool large = false;
    for (int k = 1; k < argc; ++k) {
        if (std::strcmp(argv[k], "--repeat") == 0 && k + 1 < argc) repeat = std::max(1, std::atoi(argv[++k]));
        else if (std::strcmp(argv[k], "--large") == 0) large = true;
        else {
            std::fprintf(stderr, "usage: analytic_sweep_bench [--repeat R] [--large]\n");
            return 2;
        }
    }
    // Every grid's last axes are architecture or bus settings, which leave a scene's pairs as they are.
    const std::string sweep_one_scene = " --set m=1:32:+1 --set clock-mhz=30:99:+1 --set bus.interrupt_ns=1000:5000:+1000";
    std::vector<Grid> grids{
        {"N = 2 (a point's own cost)", "--objects 2 --set seed=1:100:+1 --set m=1:30:+1", 3000, 100, true},
        {"N = 1,000, one scene", "--objects 1000" + sweep_one_scene, 11200, 1, false},
        {"N = 10,000, one scene", "--objects 10000" + sweep_one_scene, 11200, 1, false},
        {"N = 1,000, ten points a scene", "--objects 1000 --set seed=1:1000:+1 --set m=1:10:+1", 1e4, 1000, false},
        {"N = 10,000, ten points a scene", "--objects 10000 --set seed=1:100:+1 --set m=1:10:+1", 1000, 100, true},
    };
    if (large) {
        grids.push_back({"N = 1,000, 100 points a scene", "--objects 1000 --set seed=1:1000:+1 --set m=1:10:+1 "
                                                         "--set clock-mhz=30:75:+5", 1e5, 1000, false});
    }
    const fs::path out = fs::temp_directory_path() / ("cdvp-analytic-sweep-bench-" + std::to_string(getpid()));
    // The process's own start and end (loading, the sweep's files): a sweep of one point.
    std::vector<double> starts;
    for (int r = 0; r < repeat; ++r) starts.push_back(run_sweep("--objects 2 --set m=1:1:+1", "compact", out));
    const double start = median(starts);
    std::printf("A sweep of one point: %.3f s (the process's start and the sweep's files).\n\n", start);
    std::printf("| grid | points | scenes | full: points/s | compact: s | compact: points/s | "
                "compact: us a point past the start |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const Grid& g : grids) {
        std::vector<double> full, compact;
        for (int r = 0; r < repeat; ++r) {  // alternating, so that both see the same machine
            if (g.full) full.push_back(run_sweep(g.axes, "full", out));
            compact.push_back(run_sweep(g.axes, "compact", out));
        }
        const double c = median(compact);
        const std::string full_rate = g.full ? std::to_string(static_cast<long>(g.points / median(full) + 0.5)) : "";
        std::printf("| %s | %.0f | %.0f | %s | %.2f | %.0f | %.0f |\n", g.label, g.points, g.scenes, full_rate.c_str(), c,
                    g.points / c, std::max(0.0, c - start) / g.points * 1e6);
        std::fflush(stdout);
    }
    fs::remove_all(out);
    return 0;
}
