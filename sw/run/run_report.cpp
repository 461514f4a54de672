#include "sw/run/run_report.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "models/address_generator/sweep_schedule.h"
#include "models/common/user_text.h"
#include "sw/run/best_software.h"
#include "sw/run/report_provenance.h"
#include "sw/run/report_summary.h"
#include "sw/run/version.h"

namespace cdvp {

static_assert(RunTotals::kPhases == static_cast<int>(ReportSummary::kPhases), "one list of phases");

namespace {

double phase_value(const FramePhases& p, int k) {
    const double values[RunTotals::kPhases] = {p.upload_ns,   p.start_ns,  p.compute_ns, p.irq_ns,
                                               p.readback_ns, p.driver_ns, p.total_ns};
    return values[k];
}

// 'value' as nlohmann's dump(2) prints it nested 'depth' levels deep. A
// file name that is no UTF-8 (Latin-1, say) is shown with U+FFFD for its
// stray bytes: JSON text is UTF-8.
std::string nested(const nlohmann::json& value, int depth) {
    std::string text = value.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
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
                             {"origin", values.origin_words(*s)}};
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
    nlohmann::json pieces = {{"lanes", piece_json(r.lanes)},
                             {"coordinate_memories", piece_json(r.coordinate_memories)},
                             {"address_generator", piece_json(r.address_generator)},
                             {"pair_collector", piece_json(r.pair_collector)},
                             {"control", piece_json(r.control)}};
    if (r.grid_blocks.luts > 0) pieces["grid_blocks"] = piece_json(r.grid_blocks);
    return {{"device", fit.device.name},
            {"family", fit.device.family},
            {"format", format.name()},
            {"pair_fifo_memory", fifo_memory_name(r.pair_fifo_memory)},
            {"luts", usage_json(total.luts, fit.device.luts)},
            {"flip_flops", usage_json(total.flip_flops, fit.device.flip_flops)},
            {"block_rams", usage_json(total.block_rams, fit.device.block_rams)},
            {"carry_cells", total.carry_cells},
            {"fits", fit.use.fits()},
            {"largest_m", fit.largest_m},
            {"timing", timing_json(fit)},
            {"pieces", pieces}};
}

nlohmann::json config_json(const RunDescription& run) {
    const BoardConfig& c = run.config;
    nlohmann::json config = {
        {"version", kCdvpVersion},
        {"command_line", run.command_line},
        {"source", run.source},
        {"board", run.board},
        {"bus", run.bus},
        {"host", run.host},
        {"host_factor", run.host_timing.overall},
        {"host_calibration", host_calibration_json(run.host_timing)},
        {"provenance", provenance_json(read_machine_info(), run.load_average_start, run.host_timing)},
        {"transfer", name_of(run.transfer)},
        {"wait", name_of(run.wait)},
        {"fidelity", name_of(run.fidelity)},
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
    for (const auto& [name, t] : f.baselines) {
        baselines[name] = {{"native_ns", t.native_ns},
                           {"wall_native_ns", t.wall_native_ns},
                           {"host_ns", t.host_ns},
                           {"involuntary_switches", t.involuntary_switches},
                           {"migrated", t.migrated},
                           {"probe_native_ns", t.probe_native_ns}};
        if (t.native_energy_j >= 0) baselines[name]["native_energy_j"] = t.native_energy_j;
        if (t.threads_cpu_native_ns > 0) baselines[name]["threads_cpu_native_ns"] = t.threads_cpu_native_ns;
    }
    nlohmann::json frame = {{"frame", f.frame},
            {"objects", f.objects},
            {"pairs", f.pairs},
            {"compute_cycles", p.compute_cycles},
            {"stall_cycles", p.stall_cycles},
            {"sweep_cycles", f.sweep_cycles},
            {"load_wait_slots", f.load_wait_slots},
            {"overflow_pauses", p.overflow_pauses},
            {"timeouts_recovered", p.timeouts_recovered},
            {"boxes_sent", p.boxes_sent},
            {"upload_bytes", p.upload_bytes},
            {"readback_bytes", p.readback_bytes},
            {"upload_ns", p.upload_ns},
            {"start_ns", p.start_ns},
            {"compute_ns", p.compute_ns},
            {"irq_ns", p.irq_ns},
            {"readback_ns", p.readback_ns},
            {"driver_ns", p.driver_ns},
            {"total_ns", p.total_ns},
            {"overlap_ns", p.overlap_ns},
            {"latency_ns", p.latency_ns},
            {"sim_wall_native_ns", f.sim_wall_native_ns},
            {"energy_j", f.energy.total_j()},
            {"energy_static_j", f.energy.static_j},
            {"energy_dynamic_j", f.energy.dynamic_j},
            {"energy_bus_j", f.energy.bus_j},
            {"energy_host_j", f.energy.host_j},
            {"baselines", baselines}};
    add_extra(frame, f.extra);
    return frame;
}

}  // namespace

void RunTotals::add(const FrameStats& frame) {
    Sums& sums = frames_ < warmup_frames_ ? warmup_ : rest_;
    for (int k = 0; k < kPhases; ++k) sums.phases[k] += phase_value(frame.phases, k);
    sums.energy += frame.energy;
    sums.pairs += frame.pairs;
    for (const auto& [name, t] : frame.baselines) {
        baseline_samples(name).add(t.native_ns);
        baseline_wall_samples(name).add(t.wall_native_ns);
        if (t.native_energy_j >= 0) {
            auto& [joules, count] = sums.native_energy[name];
            joules += t.native_energy_j;
            ++count;
        }
    }
    board_total_.add(frame.phases.total_ns);
    latency_.add(frame.phases.latency_ns);
    sim_wall_.add(frame.sim_wall_native_ns);
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

FrameSamples& RunTotals::baseline_wall_samples(const std::string& name) {
    return baselines_wall_.try_emplace(name, warmup_frames_).first->second;
}

void RunTotals::clear_baselines() {
    baselines_.clear();
    baselines_wall_.clear();
}

void RunTotals::set_timing_quality(std::map<std::string, TimingQuality> quality, uint32_t max_tries) {
    quality_ = std::move(quality);
    max_tries_ = max_tries;
}

// Steady-state means: the warm-up frames are left out when there are more,
// since incremental broad phases build their structures in them.
double RunTotals::mean_phase(int k) const {
    if (frames_ == 0) return 0.0;
    return (frames_ > warmup_frames_ ? rest_ : warmup_).phases[k] / static_cast<double>(frames_in_means());
}

std::map<std::string, TimingFigures> RunTotals::baseline_figures() const {
    std::map<std::string, TimingFigures> figures;
    for (const auto& [name, samples] : baselines_) figures[name] = samples.figures();
    return figures;
}

void ReportWriter::begin(const RunDescription& run) {
    out_ << "{\n  \"config\": " << nested(config_json(run), 1) << ",\n  \"format_version\": " << kReportFormatVersion
         << ",\n  \"frames\": [";
}

void ReportWriter::frame(const FrameStats& frame) {
    out_ << (any_frame_ ? ",\n    " : "\n    ") << nested(frame_json(frame), 2);
    any_frame_ = true;
}

MemoryReport::MemoryReport(nlohmann::json& out) : out_(out) {
    out_ = {{"format_version", kReportFormatVersion}, {"frames", nlohmann::json::array()}};
}

void MemoryReport::frame(const FrameStats& frame) { out_["frames"].push_back(frame_json(frame)); }

void MemoryReport::end(const RunTotals& totals, const HostTiming& host) { out_["summary"] = to_json(totals.summary(host)); }

ReportSummary RunTotals::summary(const HostTiming& host) const {
    const TimingFigures board = board_figures();
    ReportSummary s;
    const std::array<double, 3> load_end = load_average();
    bool first_quality = true;
    for (const auto& [name, figures] : baseline_figures()) {
        const double factor = host.factor(name);
        BaselineSummary& b = s.baselines[name];
        b.native_ns = figures.spread;
        b.host_ns = figures.spread.scaled(factor);
        b.run_means_native_ns = figures.run_means;
        b.host_factor = factor;
        b.speedup = speedup(b.host_ns, board.spread);
        b.energy_j = software_frame_energy_j(host_w_, b.host_ns.mean);
        b.timing = timing_id_;
        if (const auto r = retimed_.find(name); r != retimed_.end()) b.retimed = r->second;
        if (const auto wall = baselines_wall_.find(name); wall != baselines_wall_.end()) {
            b.wall_native_ns = wall->second.figures().spread;
        }
        if (const auto q = quality_.find(name); q != quality_.end()) {
            b.quality = q->second;
            if (timing_id_.empty()) b.quality.load_end = load_end;  // a shared timing keeps its own
            if (first_quality) {
                s.timing_quality = b.quality;
            } else {
                s.timing_quality += b.quality;
            }
            first_quality = false;
        }
    }
    if (const std::optional<std::string> fastest = fastest_baseline(s)) s.best_software = *fastest;
    s.retime_tries = max_tries_;
    s.timing_warning = timing_warning_;
    s.frames = frames();
    s.warmup_frames = warmup_frames();
    s.frames_in_means = frames_in_means();
    s.too_few_frames = frames() > 0 && board.too_few_frames();
    s.pairs = pairs();
    s.load_average_end = load_end;
    s.extra = extra();
    s.total_ns = board.spread;
    s.latency_ns = latency_figures().spread;
    s.sim_wall_native_ns = sim_wall_figures().spread;
    for (int k = 0; k < kPhases; ++k) s.mean_phase_ns[static_cast<std::size_t>(k)] = mean_phase(k);
    put_energy(s);
    return s;
}

// The board's mean energy a frame and a pair, and each baseline's beside it
// (its energy over the board's: above 1, the board takes less).
void RunTotals::put_energy(ReportSummary& s) const {
    const Sums& sums = in_means();
    const double frames = static_cast<double>(std::max<uint64_t>(frames_in_means(), 1));
    s.host_package_w = host_w_;
    s.mean_energy.static_j = sums.energy.static_j / frames;
    s.mean_energy.dynamic_j = sums.energy.dynamic_j / frames;
    s.mean_energy.bus_j = sums.energy.bus_j / frames;
    s.mean_energy.host_j = sums.energy.host_j / frames;
    const double mean_pairs = static_cast<double>(sums.pairs) / frames;
    s.mean_energy_per_pair_j = mean_pairs > 0 ? s.mean_energy.total_j() / mean_pairs : 0;
    for (auto& [name, b] : s.baselines) {
        b.energy_per_pair_j = mean_pairs > 0 ? b.energy_j / mean_pairs : 0;
        b.energy_ratio = s.mean_energy.total_j() > 0 ? b.energy_j / s.mean_energy.total_j() : 0;
        const auto measured = sums.native_energy.find(name);
        if (measured != sums.native_energy.end() && measured->second.second > 0) {
            b.native_energy_j = measured->second.first / static_cast<double>(measured->second.second);
        }
    }
}

void ReportWriter::end(const RunTotals& totals, const HostTiming& host, const nlohmann::json* more) {
    const nlohmann::json summary = to_json(totals.summary(host));
    out_ << (any_frame_ ? "\n  ]" : "]") << ",\n  \"summary\": " << nested(summary, 1);
    if (more != nullptr) {
        for (const auto& [name, section] : more->items()) {
            out_ << ",\n  " << nlohmann::json(name).dump() << ": " << nested(section, 1);
        }
    }
    out_ << "\n}\n";
}

void describe_memory(RunDescription& run, bool ssram) {
    run.ssram = ssram;
    const SweepSchedule at_capacity(run.config.m, run.config.tiles, run.capacity);
    run.tiles = at_capacity.tiles();
    run.load_wait_slots = at_capacity.wait_slots();
}

uint64_t load_wait_slots(const RunDescription& run, uint64_t objects) {
    if (!run.ssram) return 0;
    return SweepSchedule(run.config.m, run.config.tiles, static_cast<uint32_t>(objects)).wait_slots();
}

}  // namespace cdvp
