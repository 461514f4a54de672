// cdvp sweep's throughput and overhead, measured side by side in one run:
// points per second at --jobs 1 and --jobs 2 over the same grid, and the
// sweep's own time per point (spawning, reading reports, committing the CSV)
// against the time of the point's own `cdvp run`.
//
//   ./build/tests/sweep_bench [extra sweep options, replacing the default grid]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sw/study/sweep_csv.h"
#include "sw/study/sweep_table.h"

namespace {

namespace fs = std::filesystem;

struct Measured {
    double wall_s = 0;
    std::size_t points = 0;
    double child_s = 0;      // the points' own cdvp run, spawn to exit, summed
    double sweep_cpu_s = 0;  // CPU time of the sweep process itself
    double points_cpu_s = 0; // CPU time of its children (the points)
};

Measured sweep(const std::string& grid, const fs::path& out, unsigned jobs, bool fresh = true) {
    if (fresh) fs::remove_all(out);
    const std::string command = std::string("'") + CDVP_BINARY + "' sweep " + grid + " --no-plots --jobs " +
                                std::to_string(jobs) + " --out '" + out.string() + "' 2>/dev/null";
    const auto start = std::chrono::steady_clock::now();
    FILE* pipe = popen(command.c_str(), "r");
    char summary[512] = "";
    if (pipe == nullptr || std::fgets(summary, sizeof summary, pipe) == nullptr || pclose(pipe) != 0) {
        std::fprintf(stderr, "sweep_bench: failed: %s\n", command.c_str());
        std::exit(1);
    }
    Measured m;
    m.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // "... CPU time X s in the sweep, Y s in its points and plots)"
    const char* cpu = std::strstr(summary, "CPU time ");
    if (cpu == nullptr || std::sscanf(cpu, "CPU time %lf s in the sweep, %lf s", &m.sweep_cpu_s, &m.points_cpu_s) != 2) {
        std::fprintf(stderr, "sweep_bench: no CPU times in: %s\n", summary);
        std::exit(1);
    }
    std::ifstream in(out / "sweep.csv");
    std::stringstream text;
    text << in.rdbuf();
    const auto lines = cdvp::parse_csv(text.str(), "sweep.csv");
    std::size_t wall_column = 0;
    while (wall_column < lines[0].size() && lines[0][wall_column] != "point_wall_s") ++wall_column;
    for (std::size_t k = 1; k < lines.size(); ++k) {
        ++m.points;
        if (wall_column < lines[k].size() && !lines[k][wall_column].empty()) m.child_s += std::stod(lines[k][wall_column]);
    }
    return m;
}

// The run of median wall time.
Measured median_of(std::vector<Measured> runs) {
    std::sort(runs.begin(), runs.end(), [](const Measured& a, const Measured& b) { return a.wall_s < b.wall_s; });
    return runs[runs.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    std::string grid = "--board adm-xrc-ii --set m=1,4,16 --set objects=100:800:x2 --frames 30 --baseline sap";
    if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::printf("Usage: sweep_bench [cdvp sweep options]\n"
                    "Runs one grid at --jobs 1 and --jobs 2, three times each, alternated, and prints\n"
                    "the median points per second of each and the sweep's own cost per point.\n"
                    "The options replace the default grid: %s\n", grid.c_str());
        return 0;
    }
    if (argc > 1) {
        grid.clear();
        for (int k = 1; k < argc; ++k) grid += std::string(k > 1 ? " " : "") + argv[k];
    }
    const fs::path dir = fs::temp_directory_path() / ("cdvp-sweep-bench-" + std::to_string(getpid()));
    std::printf("grid: %s\n", grid.c_str());
    // Alternated and repeated, so that a change in the machine's load hits
    // both alike; the medians are printed.
    constexpr int kRepeats = 3;
    std::vector<Measured> ones, twos;
    for (int k = 0; k < kRepeats; ++k) {
        ones.push_back(sweep(grid, dir / "jobs1", 1));
        twos.push_back(sweep(grid, dir / "jobs2", 2));
    }
    // The same command again has nothing to run: the sweep's cost per
    // sweep (starting, checking names, reading the CSV), not per point.
    const Measured again = sweep(grid, dir / "jobs1", 1, false);
    fs::remove_all(dir);
    const Measured one = median_of(ones), two = median_of(twos);
    const double rate1 = static_cast<double>(one.points) / one.wall_s;
    const double rate2 = static_cast<double>(two.points) / two.wall_s;
    std::printf("%-8s %8s %10s %12s   (median of %d runs each, alternated)\n", "jobs", "points", "wall_s", "points/s",
                kRepeats);
    std::printf("%-8d %8zu %10.3f %12.2f\n", 1, one.points, one.wall_s, rate1);
    std::printf("%-8d %8zu %10.3f %12.2f\n", 2, two.points, two.wall_s, rate2);
    std::printf("jobs 2 / jobs 1: %.2fx points per second (target >= 1.8x on two cores)\n", rate2 / rate1);
    // At --jobs 1 the sweep waits for each point in turn: what is neither
    // the points' own time nor the sweep's fixed cost is its cost per point.
    const double points = static_cast<double>(one.points);
    const double per_point = one.child_s / points;
    const double overhead = (one.wall_s - again.wall_s - one.child_s) / points;
    std::printf("per point at --jobs 1: cdvp run %.1f ms, the sweep's own %.2f ms (%.2f%%, target < 5%%)\n",
                per_point * 1e3, overhead * 1e3, 100 * overhead / per_point);
    std::printf("per sweep: %.1f ms (a rerun with every point done; %.2f%% of this grid's %.0f points)\n",
                again.wall_s * 1e3, 100 * again.wall_s / one.child_s, points);
    // CPU time does not count the waits for a CPU on a loaded machine.
    const double own_cpu = (one.sweep_cpu_s - again.sweep_cpu_s) / points;
    const double point_cpu = one.points_cpu_s / points;
    std::printf("CPU per point at --jobs 1: cdvp run %.2f ms, the sweep's own %.3f ms (%.2f%%); per sweep %.1f ms\n",
                point_cpu * 1e3, own_cpu * 1e3, 100 * own_cpu / point_cpu, again.sweep_cpu_s * 1e3);
    return 0;
}
