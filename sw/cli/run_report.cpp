#include "sw/cli/run_report.h"

#include <cstdio>

namespace cdvp {

nlohmann::json report_json(const RunSummary& run) {
    const BoardConfig& c = run.config;
    nlohmann::json frames = nlohmann::json::array();
    for (const FrameStats& f : run.frames) {
        frames.push_back({{"frame", f.frame},
                          {"objects", f.objects},
                          {"pairs", f.pairs},
                          {"compute_cycles", f.compute_cycles},
                          {"stall_cycles", f.stall_cycles},
                          {"sweep_cycles", f.sweep_cycles},
                          {"overflow_pauses", f.overflow_pauses},
                          {"compute_ns", static_cast<double>(f.compute_cycles) * 1e3 / c.clock_mhz}});
    }
    return {{"config",
             {{"source", run.source},
              {"m", c.m},
              {"lanes", c.lanes()},
              {"clock_mhz", c.clock_mhz},
              {"compare_latency_cycles", c.compare.latency_cycles},
              {"pipeline_latency_cycles", c.pipeline_latency()},
              {"fifo_depth", c.collector.fifo_depth},
              {"drain_per_cycle", c.collector.drain_per_cycle},
              {"pair_buffer_depth", c.collector.buffer_depth},
              {"capacity", run.capacity},
              {"block_rams", run.block_rams}}},
            {"frames", frames}};
}

void print_summary(std::ostream& out, const RunSummary& run) {
    const BoardConfig& c = run.config;
    char line[256];
    std::snprintf(line, sizeof line, "%s on m=%u (%u lanes), %.6g MHz, L=%u cycles, %u block RAMs\n",
                  run.source.c_str(), c.m, c.lanes(), c.clock_mhz, c.pipeline_latency(), run.block_rams);
    out << line;
    constexpr std::size_t kRowsShown = 10;
    out << "  frame  objects     pairs  S(N,m)+L  compute_cycles  stall_cycles  compute_us\n";
    uint64_t pairs = 0, cycles = 0, stalls = 0;
    for (std::size_t k = 0; k < run.frames.size(); ++k) {
        const FrameStats& f = run.frames[k];
        pairs += f.pairs;
        cycles += f.compute_cycles;
        stalls += f.stall_cycles;
        if (k < kRowsShown) {
            std::snprintf(line, sizeof line, "%7llu %8llu %9llu %9llu %15llu %13llu %11.2f\n",
                          static_cast<unsigned long long>(f.frame), static_cast<unsigned long long>(f.objects),
                          static_cast<unsigned long long>(f.pairs),
                          static_cast<unsigned long long>(f.sweep_cycles + c.pipeline_latency()),
                          static_cast<unsigned long long>(f.compute_cycles),
                          static_cast<unsigned long long>(f.stall_cycles), f.compute_cycles / c.clock_mhz);
            out << line;
        } else if (k == kRowsShown) {
            out << "    ... (" << run.frames.size() - kRowsShown << " more frames in the report)\n";
        }
    }
    std::snprintf(line, sizeof line, "total: %zu frames, %llu pairs, %llu board cycles (%llu stalled)\n",
                  run.frames.size(), static_cast<unsigned long long>(pairs),
                  static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(stalls));
    out << line;
    const double rate = run.wall_seconds > 0 ? static_cast<double>(cycles) / run.wall_seconds : 0.0;
    std::snprintf(line, sizeof line, "simulated in %.3f s wall time (%.2f M board cycles/s)\n", run.wall_seconds,
                  rate / 1e6);
    out << line;
}

}  // namespace cdvp
