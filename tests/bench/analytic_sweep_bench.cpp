// Points per second of cdvp sweep at the analytic level, its points run in
// the sweep's own process: each grid as a full record (a report a point) and
// as a compact one (a row a point), side by side in one run, medians of
// --repeat runs (default 3), and their ratio. The grids' points share scenes
// (seed x m), as a design-space sweep's do: m, clock and bus leave a scene's
// pairs as they are.
//
//   ./build/tests/analytic_sweep_bench [--repeat R] [--large]
//   --large adds 10^4 and 10^5 points at N = 1,000 (compact only)
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
    std::vector<Grid> grids{
        {"N = 2 (the sweep's own cost)", "--objects 2 --set seed=1:100:+1 --set m=1:10:+1", 1000, true},
        {"N = 1,000", "--objects 1000 --set seed=1:100:+1 --set m=1:10:+1", 1000, true},
        {"N = 10,000", "--objects 10000 --set seed=1:100:+1 --set m=1:10:+1", 1000, true},
        {"N = 10,000, one scene", "--objects 10000 --set m=1:32:+1 --set clock-mhz=33:99:+2", 1088, true},
    };
    if (large) {
        grids.push_back({"N = 1,000, 10^4 points", "--objects 1000 --set seed=1:1000:+1 --set m=1:10:+1", 1e4, false});
        grids.push_back({"N = 1,000, 10^5 points", "--objects 1000 --set seed=1:1000:+1 --set m=1:10:+1 "
                                                   "--set clock-mhz=30:75:+5", 1e5, false});
    }
    const fs::path out = fs::temp_directory_path() / ("cdvp-analytic-sweep-bench-" + std::to_string(getpid()));
    std::printf("| grid | points | full: s | full: points/s | compact: s | compact: points/s | compact / full speed |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const Grid& g : grids) {
        std::vector<double> full, compact;
        for (int r = 0; r < repeat; ++r) {  // alternating, so that both see the same machine
            if (g.full) full.push_back(run_sweep(g.axes, "full", out));
            compact.push_back(run_sweep(g.axes, "compact", out));
        }
        const double c = median(compact);
        if (g.full) {
            const double f = median(full);
            std::printf("| %s | %.0f | %.2f | %.0f | %.2f | %.0f | %.2fx |\n", g.label, g.points, f, g.points / f, c,
                        g.points / c, f / c);
        } else {
            std::printf("| %s | %.0f | | | %.2f | %.0f | |\n", g.label, g.points, c, g.points / c);
        }
        std::fflush(stdout);
    }
    fs::remove_all(out);
    return 0;
}
