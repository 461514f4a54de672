#include "sw/cli/run_report.h"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "models/address_generator/sweep_schedule.h"
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

// A resource used against what the device has (null: unbounded).
nlohmann::json usage_json(double used, double available) {
    if (std::isinf(available)) return {{"used", used}, {"available", nullptr}, {"utilisation", nullptr}};
    return {{"used", used}, {"available", available}, {"utilisation", used / available}};
}

nlohmann::json piece_json(const Resources& r) {
    return {{"luts", r.luts}, {"flip_flops", r.flip_flops}, {"carry_cells", r.carry_cells}, {"block_rams", r.block_rams}};
}

nlohmann::json resources_json(const DeviceFit& fit, NumberFormat format) {
    const Resources total = fit.resources.total();
    const BoardResources& r = fit.resources;
    return {{"device", fit.device.name},
            {"family", fit.device.family},
            {"format", format.name()},
            {"pair_fifo_memory", r.pair_fifo_memory},
            {"luts", usage_json(total.luts, fit.device.luts)},
            {"flip_flops", usage_json(total.flip_flops, fit.device.flip_flops)},
            {"block_rams", usage_json(total.block_rams, fit.device.block_rams)},
            {"carry_cells", total.carry_cells},
            {"fits", fit.use.fits()},
            {"largest_m", fit.largest_m},
            {"pieces",
             {{"lanes", piece_json(r.lanes)},
              {"coordinate_memories", piece_json(r.coordinate_memories)},
              {"address_generator", piece_json(r.address_generator)},
              {"pair_collector", piece_json(r.pair_collector)},
              {"control", piece_json(r.control)}}}};
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
        {"baseline_runs", run.baseline_runs},
        {"inject", run.inject},
        {"m", c.m},
        {"format", c.format.name()},
        {"lanes", c.lanes()},
        {"clock_mhz", c.clock_mhz},
        {"compare_latency_cycles", c.compare.latency_cycles},
        {"pipeline_latency_cycles", c.pipeline_latency()},
        {"fifo_depth", c.collector.fifo_depth},
        {"drain_per_cycle", c.collector.drain_per_cycle},
        {"pair_buffer_depth", c.collector.buffer_depth},
        {"capacity", run.capacity},
        {"block_rams", run.block_rams},
        {"memory", run.ssram ? "SSRAM" : "block RAM"},
        {"tile_boxes", c.tiles.boxes},
        {"tiles", run.tiles},
        {"load_wait_slots", run.load_wait_slots}};
    if (run.settings != nullptr) {
        config["seed"] = run.settings->settings().scene.seed;
        config["settings"] = settings_json(*run.settings);
    }
    if (run.device_fit) config["resources"] = resources_json(*run.device_fit, c.format);
    config["budgets"] = {{"memory_bytes", run.budgets.memory_bytes},
                         {"pairs_per_frame", run.budgets.pairs},
                         {"estimate_before_pairs_bytes", run.budgets.estimate_bytes},
                         {"estimate_bytes_per_pair", run.budgets.bytes_per_pair},
                         {"simulated_time_limit_s", ns_from_fs(kSimulatedTimeLimit) * 1e-9}};
    return config;
}

// Pairs against the float32 reference and the extra pairs' cost downstream.
void add_extra(nlohmann::json& json, const ExtraPairs& e) {
    json["reference_pairs"] = e.reference_pairs;
    json["extra_pairs"] = e.extra_pairs;
    json["extra_share"] = e.share();
    json["extra_readback_ns"] = e.extra_readback_ns;
    json["extra_driver_ns"] = e.extra_driver_ns;
}

nlohmann::json frame_json(const FrameStats& f) {
    const FramePhases& p = f.phases;
    nlohmann::json baselines = nlohmann::json::object();
    for (const auto& [name, t] : f.baselines) baselines[name] = {{"ns", t.ns}, {"scaled_ns", t.scaled_ns}};
    nlohmann::json frame = {{"frame", f.frame},
            {"objects", f.objects},
            {"pairs", f.pairs},
            {"compute_cycles", p.compute_cycles},
            {"stall_cycles", p.stall_cycles},
            {"sweep_cycles", f.sweep_cycles},
            {"load_wait_slots", f.load_wait_slots},
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
    add_extra(frame, f.extra);
    return frame;
}

// median_KEY, p10_KEY and p90_KEY: flat, like the mean_ keys beside them.
void add_spread(nlohmann::json& summary, const std::string& key, const Spread& s) {
    summary["median_" + key] = s.median;
    summary["p10_" + key] = s.p10;
    summary["p90_" + key] = s.p90;
}

// Which frames the figures rest on, and a note when they are too few.
std::string frames_described(const RunTotals& totals, const TimingFigures& figures) {
    std::string text = std::to_string(figures.frames_per_run) + " frames";
    if (figures.includes_warmup) return text + ", all warm-up frames (no frame came after the --warmup " +
                                        std::to_string(totals.warmup_frames()) + ")";
    if (totals.warmup_frames() > 0) text += " after " + std::to_string(totals.warmup_frames()) + " warm-up";
    return text;
}

// The medians the speedups are taken from, with p10 and p90.
void print_timing(std::ostream& out, const RunConfig& run, const RunTotals& totals) {
    if (totals.frames() == 0) return;
    const TimingFigures board = totals.board_figures();
    const std::map<std::string, TimingFigures> baselines = totals.baseline_figures();
    char line[512];
    out << "\nper frame, median of " << frames_described(totals, board);
    if (!baselines.empty()) {
        std::snprintf(line, sizeof line, ", software time x %.3g on host ", run.host_factor);
        out << line << printable(run.host);
        if (run.baseline_runs > 1) {
            out << ", software timed in " << run.baseline_runs << " runs (median of their medians)";
        }
    }
    std::snprintf(line, sizeof line, ":\n  board: %.1f us (p10 %.1f, p90 %.1f), simulated: the same on every run\n",
                  board.spread.median / 1e3, board.spread.p10 / 1e3, board.spread.p90 / 1e3);
    out << line;
    const Spread wall = totals.sim_wall_figures().spread;
    std::snprintf(line, sizeof line, "  simulator: %.3f ms wall time (p10 %.3f, p90 %.3f)\n", wall.median / 1e6,
                  wall.p10 / 1e6, wall.p90 / 1e6);
    out << line;
    if (!baselines.empty()) {
        out << "      N    m   board_us  software          sw_us     sw_p10     sw_p90  speedup\n";
        for (const auto& [name, figures] : baselines) {
            const Spread sw = figures.spread.scaled(run.host_factor);
            std::snprintf(line, sizeof line, "%7llu %4u %10.1f  %-8s %13.1f %10.1f %10.1f %7.2fx\n",
                          static_cast<unsigned long long>(totals.last_objects()), run.config.m,
                          board.spread.median / 1e3, name.c_str(), sw.median / 1e3, sw.p10 / 1e3, sw.p90 / 1e3,
                          speedup(sw.median, board));
            out << line;
        }
    }
    if (board.too_few_frames()) {
        out << "note: these figures rest on " << board.frames_per_run << " frames, fewer than " << kMinMeasuredFrames
            << ": one disturbed frame can move a median, and p10 and p90 are near the extremes; give --frames "
            << totals.warmup_frames() + kMinMeasuredFrames << " or more\n";
    }
}

}  // namespace

void RunTotals::add(const FrameStats& frame) {
    Sums& sums = frames_ < warmup_frames_ ? warmup_ : rest_;
    for (int k = 0; k < kPhases; ++k) sums.phases[k] += phase_value(frame.phases, k);
    for (const auto& [name, t] : frame.baselines) {
        sums.baselines[name].ns += t.ns;
        sums.baselines[name].scaled_ns += t.scaled_ns;
        baseline_samples(name).add(t.ns);
    }
    board_total_.add(frame.phases.total_ns);
    sim_wall_.add(frame.sim_wall_ns);
    ++frames_;
    pairs_ += frame.pairs;
    cycles_ += frame.phases.compute_cycles;
    stalls_ += frame.phases.stall_cycles;
    last_objects_ = frame.objects;
    extra_ += frame.extra;
    if (shown_.size() < kRowsShown) shown_.push_back(frame);
}

FrameSamples& RunTotals::baseline_samples(const std::string& name) {
    return baselines_.try_emplace(name, warmup_frames_).first->second;
}

// Steady-state means: the warm-up frames are left out when there are more,
// since incremental broad phases build their structures in them.
double RunTotals::mean_phase(int k) const {
    if (frames_ == 0) return 0.0;
    return (frames_ > warmup_frames_ ? rest_ : warmup_).phases[k] / static_cast<double>(frames_in_means());
}

std::map<std::string, BaselineTime> RunTotals::mean_baselines() const {
    std::map<std::string, BaselineTime> means;
    if (frames_ == 0) return means;
    const double n = static_cast<double>(frames_in_means());
    for (const auto& [name, t] : (frames_ > warmup_frames_ ? rest_ : warmup_).baselines) {
        means[name] = {t.ns / n, t.scaled_ns / n};
    }
    return means;
}

std::map<std::string, TimingFigures> RunTotals::baseline_figures() const {
    std::map<std::string, TimingFigures> figures;
    for (const auto& [name, samples] : baselines_) figures[name] = samples.figures();
    return figures;
}

double speedup(double scaled_median_ns, const TimingFigures& board) {
    return board.spread.median > 0 ? scaled_median_ns / board.spread.median : 0.0;
}

void ReportWriter::begin(const RunConfig& run) {
    out_ << "{\n  \"config\": " << nested(config_json(run), 1) << ",\n  \"frames\": [";
}

void ReportWriter::frame(const FrameStats& frame) {
    out_ << (any_frame_ ? ",\n    " : "\n    ") << nested(frame_json(frame), 2);
    any_frame_ = true;
}

void ReportWriter::end(const RunTotals& totals, double host_factor) {
    const TimingFigures board = totals.board_figures();
    const std::map<std::string, BaselineTime> means = totals.mean_baselines();
    nlohmann::json baselines = nlohmann::json::object();
    for (const auto& [name, figures] : totals.baseline_figures()) {
        const Spread native = figures.spread, scaled = native.scaled(host_factor);
        const auto mean = means.find(name);
        baselines[name] = {{"median_ns", native.median},
                           {"p10_ns", native.p10},
                           {"p90_ns", native.p90},
                           {"median_scaled_ns", scaled.median},
                           {"p10_scaled_ns", scaled.p10},
                           {"p90_scaled_ns", scaled.p90},
                           {"run_medians_ns", figures.run_medians},
                           {"mean_ns", mean != means.end() ? mean->second.ns : 0.0},
                           {"mean_scaled_ns", mean != means.end() ? mean->second.scaled_ns : 0.0},
                           {"speedup", speedup(scaled.median, board)}};
    }
    nlohmann::json summary = {{"frames", totals.frames()},
                              {"warmup_frames", totals.warmup_frames()},
                              {"frames_in_means", totals.frames_in_means()},
                              {"too_few_frames", totals.frames() > 0 && board.too_few_frames()},
                              {"baselines", baselines},
                              {"pairs", totals.pairs()}};
    add_extra(summary, totals.extra());
    add_spread(summary, "total_ns", board.spread);
    add_spread(summary, "sim_wall_ns", totals.sim_wall_figures().spread);
    for (int k = 0; k < RunTotals::kPhases; ++k) summary[std::string("mean_") + kPhaseNames[k]] = totals.mean_phase(k);
    out_ << (any_frame_ ? "\n  ]" : "]") << ",\n  \"summary\": " << nested(summary, 1) << "\n}\n";
}

namespace {

void print_resources(std::ostream& out, const DeviceFit& fit) {
    const Resources total = fit.resources.total();
    std::string text = "  on " + printable(fit.device.name) + " (synthesis for " + fit.device.family + "):";
    const auto usage = [&](const char* name, double used, double available) {
        char part[128];
        if (std::isinf(available)) {
            std::snprintf(part, sizeof part, " %.0f %s,", used, name);
        } else {
            std::snprintf(part, sizeof part, " %.0f of %.0f %s (%.0f%%),", used, available, name,
                          100 * used / available);
        }
        text += part;
    };
    usage("LUTs", total.luts, fit.device.luts);
    usage("flip-flops", total.flip_flops, fit.device.flip_flops);
    usage("block RAMs", total.block_rams, fit.device.block_rams);
    text += " pair FIFO in " + std::string(fit.resources.pair_fifo_memory == "block_ram" ? "block RAM" : "LUTs");
    text += fit.use.fits() ? "; largest m that fits: " + std::to_string(fit.largest_m) + "\n"
                           : "; does not fit (" + fit.use.overflow + ")\n";
    out << text;
}

}  // namespace

void describe_memory(RunConfig& run, bool ssram) {
    run.ssram = ssram;
    const SweepSchedule at_capacity(run.config.m, run.config.tiles, run.capacity);
    run.tiles = at_capacity.tiles();
    run.load_wait_slots = at_capacity.wait_slots();
}

uint64_t load_wait_slots(const RunConfig& run, uint64_t objects) {
    if (!run.ssram) return 0;
    return SweepSchedule(run.config.m, run.config.tiles, static_cast<uint32_t>(objects)).wait_slots();
}

void print_summary(std::ostream& out, const RunConfig& run, const RunTotals& totals, double wall_seconds) {
    const BoardConfig& c = run.config;
    char line[512];
    // Names may be long and come from files: printed whole and escaped.
    std::snprintf(line, sizeof line, ": m=%u (%u %s lanes), %.6g MHz, L=%u cycles, %u block RAMs, %s engine\n", c.m,
                  c.lanes(), c.format.name().c_str(), c.clock_mhz, c.pipeline_latency(), run.block_rams,
                  run.fidelity.c_str());
    out << printable(run.source) << " on " << printable(run.board) << " (" << printable(run.bus) << ")" << line;
    if (run.device_fit) print_resources(out, *run.device_fit);
    if (run.ssram) {
        std::snprintf(line, sizeof line,
                      "  boxes in SSRAM: %u tiles of %u boxes at %u objects, %llu slots waiting for tile loads\n",
                      run.tiles, c.tiles.boxes, run.capacity, static_cast<unsigned long long>(run.load_wait_slots));
        out << line;
    }
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
    if (!c.format.is_float()) {
        const ExtraPairs& e = totals.extra();
        std::snprintf(line, sizeof line,
                      "%s: %llu pairs of the float32 reference, %llu extra (%.2f%% of the board's), costing %.1f us "
                      "of readback and %.1f us of driver time\n",
                      c.format.name().c_str(), static_cast<unsigned long long>(e.reference_pairs),
                      static_cast<unsigned long long>(e.extra_pairs), 100 * e.share(), e.extra_readback_ns / 1e3,
                      e.extra_driver_ns / 1e3);
        out << line;
    }
    print_timing(out, run, totals);
    const double rate = wall_seconds > 0 ? static_cast<double>(totals.cycles()) / wall_seconds : 0.0;
    std::snprintf(line, sizeof line, "simulated in %.3f s wall time (%.2f M board cycles/s)\n", wall_seconds,
                  rate / 1e6);
    out << line;
}

}  // namespace cdvp
