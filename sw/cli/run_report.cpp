#include "sw/cli/run_report.h"

#include <cstdio>

namespace cdvp {

namespace {

nlohmann::json config_json(const RunSummary& run) {
    const BoardConfig& c = run.config;
    return {{"source", run.source},
            {"board", run.board},
            {"bus", run.bus},
            {"host", run.host},
            {"host_factor", run.host_factor},
            {"transfer", run.dma ? "dma" : "pio"},
            {"wait", run.interrupts ? "irq" : "poll"},
            {"fidelity", run.fidelity},
            {"quantum_ns", run.quantum_ns},
            {"baselines", run.baseline_names},
            {"inject", run.inject},
            {"m", c.m},
            {"lanes", c.lanes()},
            {"clock_mhz", c.clock_mhz},
            {"compare_latency_cycles", c.compare.latency_cycles},
            {"pipeline_latency_cycles", c.pipeline_latency()},
            {"fifo_depth", c.collector.fifo_depth},
            {"drain_per_cycle", c.collector.drain_per_cycle},
            {"pair_buffer_depth", c.collector.buffer_depth},
            {"capacity", run.capacity},
            {"block_rams", run.block_rams}};
}

nlohmann::json frame_json(const FrameStats& f) {
    const FramePhases& p = f.phases;
    nlohmann::json baselines = nlohmann::json::object();
    for (const auto& [name, t] : f.baselines) baselines[name] = {{"ns", t.ns}, {"scaled_ns", t.scaled_ns}};
    return {{"frame", f.frame},
            {"objects", f.objects},
            {"pairs", f.pairs},
            {"compute_cycles", p.compute_cycles},
            {"stall_cycles", p.stall_cycles},
            {"sweep_cycles", f.sweep_cycles},
            {"overflow_pauses", p.overflow_pauses},
            {"timeouts_recovered", p.timeouts_recovered},
            {"upload_ns", p.upload_ns},
            {"start_ns", p.start_ns},
            {"compute_ns", p.compute_ns},
            {"irq_ns", p.irq_ns},
            {"readback_ns", p.readback_ns},
            {"driver_ns", p.driver_ns},
            {"total_ns", p.total_ns},
            {"baselines", baselines}};
}

struct Means {
    double board_ns = 0;
    std::map<std::string, BaselineTime> baselines;
};

// Steady-state means: with more than one frame the first is left out, since
// incremental broad phases build their structures in it (Bullet's SAP takes
// tens of times its per-frame cost there).
std::size_t first_counted(const RunSummary& run) { return run.frames.size() > 1 ? 1 : 0; }

Means means(const RunSummary& run) {
    Means m;
    if (run.frames.empty()) return m;
    const double n = static_cast<double>(run.frames.size() - first_counted(run));
    for (std::size_t k = first_counted(run); k < run.frames.size(); ++k) {
        const FrameStats& f = run.frames[k];
        m.board_ns += f.phases.total_ns / n;
        for (const auto& [name, t] : f.baselines) {
            m.baselines[name].ns += t.ns / n;
            m.baselines[name].scaled_ns += t.scaled_ns / n;
        }
    }
    return m;
}

}  // namespace

nlohmann::json report_json(const RunSummary& run) {
    nlohmann::json frames = nlohmann::json::array();
    for (const FrameStats& f : run.frames) frames.push_back(frame_json(f));
    const Means m = means(run);
    nlohmann::json phases = nlohmann::json::object();
    const char* names[] = {"upload_ns", "start_ns", "compute_ns", "irq_ns", "readback_ns", "driver_ns", "total_ns"};
    const std::size_t first = first_counted(run);
    for (const char* name : names) {
        double sum = 0;
        for (std::size_t k = first; k < frames.size(); ++k) sum += frames[k][name].get<double>();
        phases[std::string("mean_") + name] = frames.empty() ? 0.0 : sum / static_cast<double>(frames.size() - first);
    }
    nlohmann::json baselines = nlohmann::json::object();
    for (const auto& [name, t] : m.baselines) {
        // Speedup of the board over the software on the modelled host.
        baselines[name] = {{"mean_ns", t.ns},
                           {"mean_scaled_ns", t.scaled_ns},
                           {"speedup", m.board_ns > 0 ? t.scaled_ns / m.board_ns : 0.0}};
    }
    nlohmann::json summary = {
        {"frames", run.frames.size()}, {"frames_in_means", run.frames.size() - first}, {"baselines", baselines}};
    summary.update(phases);
    return {{"config", config_json(run)}, {"frames", frames}, {"summary", summary}};
}

void print_summary(std::ostream& out, const RunSummary& run) {
    const BoardConfig& c = run.config;
    char line[512];
    std::snprintf(line, sizeof line, "%s on %s (%s): m=%u (%u lanes), %.6g MHz, L=%u cycles, %u block RAMs\n",
                  run.source.c_str(), run.board.c_str(), run.bus.c_str(), c.m, c.lanes(), c.clock_mhz,
                  c.pipeline_latency(), run.block_rams);
    out << line;
    constexpr std::size_t kRowsShown = 10;
    out << "  frame  objects     pairs  S(N,m)+L  compute_cycles  stall_cycles  compute_us  total_us\n";
    uint64_t pairs = 0, cycles = 0, stalls = 0;
    for (std::size_t k = 0; k < run.frames.size(); ++k) {
        const FrameStats& f = run.frames[k];
        pairs += f.pairs;
        cycles += f.phases.compute_cycles;
        stalls += f.phases.stall_cycles;
        if (k < kRowsShown) {
            std::snprintf(line, sizeof line, "%7llu %8llu %9llu %9llu %15llu %13llu %11.2f %9.2f\n",
                          static_cast<unsigned long long>(f.frame), static_cast<unsigned long long>(f.objects),
                          static_cast<unsigned long long>(f.pairs),
                          static_cast<unsigned long long>(f.sweep_cycles + c.pipeline_latency()),
                          static_cast<unsigned long long>(f.phases.compute_cycles),
                          static_cast<unsigned long long>(f.phases.stall_cycles), f.phases.compute_ns / 1e3,
                          f.phases.total_ns / 1e3);
            out << line;
        } else if (k == kRowsShown) {
            out << "    ... (" << run.frames.size() - kRowsShown << " more frames in the report)\n";
        }
    }
    std::snprintf(line, sizeof line, "total: %zu frames, %llu pairs, %llu board cycles (%llu stalled)\n",
                  run.frames.size(), static_cast<unsigned long long>(pairs),
                  static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(stalls));
    out << line;
    const Means m = means(run);
    if (!m.baselines.empty()) {
        std::snprintf(line, sizeof line, "\nmean per frame%s on host %s (software time x %.3g):\n",
                      first_counted(run) ? " after the first" : "", run.host.c_str(), run.host_factor);
        out << line << "      N    m   board_us  software          sw_us  speedup\n";
        const uint64_t n = run.frames.empty() ? 0 : run.frames.back().objects;
        for (const auto& [name, t] : m.baselines) {
            std::snprintf(line, sizeof line, "%7llu %4u %10.1f  %-8s %13.1f %7.2fx\n", static_cast<unsigned long long>(n),
                          c.m, m.board_ns / 1e3, name.c_str(), t.scaled_ns / 1e3,
                          m.board_ns > 0 ? t.scaled_ns / m.board_ns : 0.0);
            out << line;
        }
    }
    const double rate = run.wall_seconds > 0 ? static_cast<double>(cycles) / run.wall_seconds : 0.0;
    std::snprintf(line, sizeof line, "simulated in %.3f s wall time (%.2f M board cycles/s)\n", run.wall_seconds,
                  rate / 1e6);
    out << line;
}

}  // namespace cdvp
