#include "sw/cli/run_report.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "models/common/user_text.h"
#include "sw/cli/version.h"

namespace cdvp {

const char* const kPhaseNames[RunTotals::kPhases] = {"upload_ns",   "start_ns",  "compute_ns", "irq_ns",
                                                     "readback_ns", "driver_ns", "total_ns"};

namespace {

double phase_value(const FramePhases& p, int k) {
    const double values[RunTotals::kPhases] = {p.upload_ns,   p.start_ns,  p.compute_ns, p.irq_ns,
                                               p.readback_ns, p.driver_ns, p.total_ns};
    return values[k];
}

// 'value' as nlohmann's dump(2) prints it nested 'depth' levels deep.
std::string nested(const nlohmann::json& value, int depth) {
    std::string text = value.dump(2);
    const std::string indent(static_cast<std::size_t>(2 * depth), ' ');
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {  // strings hold no raw line ends: JSON escapes them
        out += c;
        if (c == '\n') out += indent;
    }
    return out;
}

// Every setting in effect: its value and where it came from.
nlohmann::json settings_json(const SettingValues& values) {
    nlohmann::json settings = nlohmann::json::object();
    for (const Setting* s : values.effective()) {
        settings[s->name] = {{"value", to_json(s->get(values.settings()))},
                             {"origin", values.origin(*s).describe(*s)}};
    }
    return settings;
}

nlohmann::json config_json(const RunConfig& run) {
    const BoardConfig& c = run.config;
    nlohmann::json config = {
        {"version", kCdvpVersion},
        {"command_line", run.command_line},
        {"source", run.source},
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
    if (run.settings != nullptr) {
        config["seed"] = run.settings->settings().scene.seed;
        config["settings"] = settings_json(*run.settings);
    }
    return config;
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
            {"sim_wall_ns", f.sim_wall_ns},
            {"baselines", baselines}};
}

}  // namespace

void RunTotals::add(const FrameStats& frame) {
    Sums& sums = frames_ == 0 ? first_ : rest_;
    for (int k = 0; k < kPhases; ++k) sums.phases[k] += phase_value(frame.phases, k);
    for (const auto& [name, t] : frame.baselines) {
        sums.baselines[name].ns += t.ns;
        sums.baselines[name].scaled_ns += t.scaled_ns;
    }
    ++frames_;
    pairs_ += frame.pairs;
    cycles_ += frame.phases.compute_cycles;
    stalls_ += frame.phases.stall_cycles;
    last_objects_ = frame.objects;
    if (shown_.size() < kRowsShown) shown_.push_back(frame);
}

// Steady-state means: with more than one frame the first is left out, since
// incremental broad phases build their structures in it (Bullet's SAP takes
// tens of times its per-frame cost there).
double RunTotals::mean_phase(int k) const {
    if (frames_ == 0) return 0.0;
    return (frames_ > 1 ? rest_ : first_).phases[k] / static_cast<double>(frames_in_means());
}

std::map<std::string, BaselineTime> RunTotals::mean_baselines() const {
    std::map<std::string, BaselineTime> means;
    if (frames_ == 0) return means;
    const double n = static_cast<double>(frames_in_means());
    for (const auto& [name, t] : (frames_ > 1 ? rest_ : first_).baselines) means[name] = {t.ns / n, t.scaled_ns / n};
    return means;
}

void ReportWriter::begin(const RunConfig& run) {
    out_ << "{\n  \"config\": " << nested(config_json(run), 1) << ",\n  \"frames\": [";
}

void ReportWriter::frame(const FrameStats& frame) {
    out_ << (any_frame_ ? ",\n    " : "\n    ") << nested(frame_json(frame), 2);
    any_frame_ = true;
}

void ReportWriter::end(const RunTotals& totals) {
    const double board_ns = totals.mean_phase(RunTotals::kPhases - 1);
    nlohmann::json baselines = nlohmann::json::object();
    for (const auto& [name, t] : totals.mean_baselines()) {
        // Speedup of the board over the software on the modelled host.
        baselines[name] = {{"mean_ns", t.ns},
                           {"mean_scaled_ns", t.scaled_ns},
                           {"speedup", board_ns > 0 ? t.scaled_ns / board_ns : 0.0}};
    }
    nlohmann::json summary = {
        {"frames", totals.frames()}, {"frames_in_means", totals.frames_in_means()}, {"baselines", baselines}};
    for (int k = 0; k < RunTotals::kPhases; ++k) summary[std::string("mean_") + kPhaseNames[k]] = totals.mean_phase(k);
    out_ << (any_frame_ ? "\n  ]" : "]") << ",\n  \"summary\": " << nested(summary, 1) << "\n}\n";
}

void print_summary(std::ostream& out, const RunConfig& run, const RunTotals& totals, double wall_seconds) {
    const BoardConfig& c = run.config;
    char line[512];
    // Names may be long and come from files: printed whole and escaped.
    std::snprintf(line, sizeof line, ": m=%u (%u lanes), %.6g MHz, L=%u cycles, %u block RAMs, %s engine\n", c.m,
                  c.lanes(), c.clock_mhz, c.pipeline_latency(), run.block_rams, run.fidelity.c_str());
    out << printable(run.source) << " on " << printable(run.board) << " (" << printable(run.bus) << ")" << line;
    out << "  frame  objects     pairs  S(N,m)+L  compute_cycles  stall_cycles  compute_us  total_us\n";
    for (const FrameStats& f : totals.shown()) {
        std::snprintf(line, sizeof line, "%7llu %8llu %9llu %9llu %15llu %13llu %11.2f %9.2f\n",
                      static_cast<unsigned long long>(f.frame), static_cast<unsigned long long>(f.objects),
                      static_cast<unsigned long long>(f.pairs),
                      static_cast<unsigned long long>(f.sweep_cycles + c.pipeline_latency()),
                      static_cast<unsigned long long>(f.phases.compute_cycles),
                      static_cast<unsigned long long>(f.phases.stall_cycles), f.phases.compute_ns / 1e3,
                      f.phases.total_ns / 1e3);
        out << line;
    }
    if (totals.frames() > totals.shown().size()) {
        out << "    ... (" << totals.frames() - totals.shown().size() << " more frames in the report)\n";
    }
    std::snprintf(line, sizeof line, "total: %llu frames, %llu pairs, %llu board cycles (%llu stalled)\n",
                  static_cast<unsigned long long>(totals.frames()), static_cast<unsigned long long>(totals.pairs()),
                  static_cast<unsigned long long>(totals.cycles()), static_cast<unsigned long long>(totals.stalls()));
    out << line;
    const double board_ns = totals.mean_phase(RunTotals::kPhases - 1);
    const std::map<std::string, BaselineTime> baselines = totals.mean_baselines();
    if (!baselines.empty()) {
        std::snprintf(line, sizeof line, " (software time x %.3g):\n", run.host_factor);
        out << "\nmean per frame" << (totals.frames() > 1 ? " after the first" : "") << " on host "
            << printable(run.host) << line << "      N    m   board_us  software          sw_us  speedup\n";
        for (const auto& [name, t] : baselines) {
            std::snprintf(line, sizeof line, "%7llu %4u %10.1f  %-8s %13.1f %7.2fx\n",
                          static_cast<unsigned long long>(totals.last_objects()), c.m, board_ns / 1e3, name.c_str(),
                          t.scaled_ns / 1e3, board_ns > 0 ? t.scaled_ns / board_ns : 0.0);
            out << line;
        }
    }
    const double rate = wall_seconds > 0 ? static_cast<double>(totals.cycles()) / wall_seconds : 0.0;
    std::snprintf(line, sizeof line, "simulated in %.3f s wall time (%.2f M board cycles/s)\n", wall_seconds,
                  rate / 1e6);
    out << line;
}

}  // namespace cdvp
