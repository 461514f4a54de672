// cdvp sweep's own cost per point as the sweep grows: sweeps of P identical
// tiny points (one frame of two spheres, a seed axis of P values) at
// --jobs 1, for each P asked, repeated; per P the medians over repeats of
//   - the sweep process's own CPU time per point (from its summary line:
//     starting each point, reading its report, appending its row), and
//   - the rate of points in the last tenth of the sweep against the first
//     tenth (from the report files' modification times): a cost that grew
//     with the points done would show as a ratio below 1.
//
//   ./build/tests/sweep_scaling_bench [--repeat R] [P ...]    (default: R = 3; P = 100 1000 10000)
#include <sys/stat.h>
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

struct Measured {
    double wall_s = 0;
    double sweep_cpu_s = 0;   // CPU time of the sweep process itself
    double points_cpu_s = 0;  // CPU time of its children
    double tail_rate_ratio = 0;  // points per second in the last tenth / in the first tenth
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// Points per second over the k-th tenth of the sorted completion times.
double tenth_rate(const std::vector<double>& times, std::size_t k) {
    const std::size_t n = times.size();
    const std::size_t from = k * n / 10, to = (k + 1) * n / 10 - 1;
    const double span = times[to] - times[from];
    return span > 0 ? static_cast<double>(to - from) / span : 0;
}

Measured sweep(std::size_t points, const fs::path& out) {
    fs::remove_all(out);
    const std::string command = std::string("'") + CDVP_BINARY + "' sweep --set seed=1:" + std::to_string(points) +
                                ":+1 --objects 2 --frames 1 --no-plots --jobs 1 --out '" + out.string() +
                                "' 2>/dev/null";
    const auto start = std::chrono::steady_clock::now();
    FILE* pipe = popen(command.c_str(), "r");
    char summary[512] = "";
    if (pipe == nullptr || std::fgets(summary, sizeof summary, pipe) == nullptr || pclose(pipe) != 0) {
        std::fprintf(stderr, "sweep_scaling_bench: failed: %s\n", command.c_str());
        std::exit(1);
    }
    Measured m;
    m.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const char* cpu = std::strstr(summary, "CPU time ");
    if (cpu == nullptr || std::sscanf(cpu, "CPU time %lf s in the sweep, %lf s", &m.sweep_cpu_s, &m.points_cpu_s) != 2) {
        std::fprintf(stderr, "sweep_scaling_bench: no CPU times in: %s\n", summary);
        std::exit(1);
    }
    std::vector<double> done;
    for (const auto& entry : fs::directory_iterator(out / "points")) {
        struct stat status {};
        stat(entry.path().c_str(), &status);
        done.push_back(static_cast<double>(status.st_mtim.tv_sec) + static_cast<double>(status.st_mtim.tv_nsec) * 1e-9);
    }
    std::sort(done.begin(), done.end());
    if (done.size() >= 20) m.tail_rate_ratio = tenth_rate(done, 9) / tenth_rate(done, 0);
    fs::remove_all(out);
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    int repeats = 3;
    std::vector<std::size_t> sizes;
    for (int k = 1; k < argc; ++k) {
        if (std::strcmp(argv[k], "--repeat") == 0 && k + 1 < argc) {
            repeats = std::max(1, std::atoi(argv[++k]));
        } else if (std::strcmp(argv[k], "--help") == 0 || std::strcmp(argv[k], "-h") == 0) {
            std::printf("Usage: sweep_scaling_bench [--repeat R] [POINTS...]\n"
                        "Sweeps grids of POINTS points (default 100 1000 10000) at --jobs 1, R times each\n"
                        "(default 3), and prints the medians of the wall and CPU time per point and the\n"
                        "last tenth's time per point over the first's.\n");
            return 0;
        } else {
            char* end = nullptr;
            const unsigned long long points = std::strtoull(argv[k], &end, 10);
            if (end == argv[k] || *end != '\0' || points == 0) {
                std::fprintf(stderr, "sweep_scaling_bench: %s is not a number of points (expected a positive integer)\n",
                             argv[k]);
                return 2;
            }
            sizes.push_back(static_cast<std::size_t>(points));
        }
    }
    if (sizes.empty()) sizes = {100, 1000, 10000};
    const fs::path dir = fs::temp_directory_path() / ("cdvp-sweep-scaling-" + std::to_string(getpid()));
    std::printf("%10s %14s %16s %16s %14s   (medians of %d runs, --jobs 1)\n", "points", "wall per point",
                "sweep CPU/point", "point CPU/point", "last/first tenth", repeats);
    for (std::size_t points : sizes) {
        std::vector<double> wall, own, child, ratio;
        for (int r = 0; r < repeats; ++r) {
            const Measured m = sweep(points, dir);
            const double n = static_cast<double>(points);
            wall.push_back(m.wall_s / n);
            own.push_back(m.sweep_cpu_s / n);
            child.push_back(m.points_cpu_s / n);
            ratio.push_back(m.tail_rate_ratio);
        }
        std::printf("%10zu %11.2f ms %13.3f ms %13.2f ms %16.2f\n", points, median(wall) * 1e3, median(own) * 1e3,
                    median(child) * 1e3, median(ratio));
        std::fflush(stdout);
    }
    fs::remove_all(dir);
    return 0;
}
