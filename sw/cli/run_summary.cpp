// The summary `cdvp run` prints: the board and its resources, the first
// frames, the totals, and the timing figures the speedups rest on.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "models/common/user_text.h"
#include "sw/run/machine_info.h"
#include "sw/cli/command_observer.h"
#include "sw/run/report_summary.h"
#include "sw/run/run_report.h"

namespace cdvp {

namespace {

void print_resources(std::ostream& out, const DeviceFit& fit) {
    const Resources total = fit.resources.total();
    std::string text = "  on " + printable(fit.device.name) + " (synthesis for " + fit.device.family + "):";
    const auto usage = [&](const char* name, double used, double available, const std::string& detail = "") {
        char part[160];
        if (std::isinf(available)) {
            std::snprintf(part, sizeof part, " %.0f %s%s,", used, name, detail.empty() ? "" : (" (" + detail + ")").c_str());
        } else {
            std::snprintf(part, sizeof part, " %.0f of %.0f %s (%.0f%%%s),", used, available, name,
                          100 * used / available, detail.empty() ? "" : ("; " + detail).c_str());
        }
        text += part;
    };
    usage("LUTs", total.luts, fit.device.luts);
    usage("flip-flops", total.flip_flops, fit.device.flip_flops);
    // The block RAMs the boxes take (the first line's count; the grid
    // board's cell buffer) and the rest.
    const double boxes = fit.resources.coordinate_memories.block_rams;
    char split[128];
    std::snprintf(split, sizeof split, "%.0f for %s, %.0f besides", boxes, fit.resources.memories_hold,
                  total.block_rams - boxes);
    usage("block RAMs", total.block_rams, fit.device.block_rams, split);
    text += " pair FIFO in " + std::string(fit.resources.pair_fifo_memory == FifoMemory::kBlockRam ? "block RAM" : "LUTs");
    text += fit.use.fits() ? "; largest m that fits: " + std::to_string(fit.largest_m)
                           : "; does not fit (" + fit.use.overflow + ")";
    text += "; " + timing_summary(fit) + "\n";
    out << text;
}

// "1 frame", "12 frames".
std::string frames_text(uint64_t frames) { return std::to_string(frames) + (frames == 1 ? " frame" : " frames"); }

// Which frames the figures rest on, and a note when they are too few.
std::string frames_described(const RunTotals& totals, const TimingFigures& figures) {
    std::string text = frames_text(figures.frames_per_run);
    if (figures.includes_warmup) return text + ", all warm-up frames (no frame came after the --warmup " +
                                        std::to_string(totals.warmup_frames()) + ")";
    if (totals.warmup_frames() > 0) text += " after " + std::to_string(totals.warmup_frames()) + " warm-up";
    return text;
}

// One line: whether the software's timing held still, and if not, which
// baselines and how (the load at its end as the summary is printed).
void print_timing_quality(std::ostream& out, const RunDescription& run, const RunTotals& totals) {
    const std::map<std::string, TimingQuality>& quality = totals.timing_quality();
    if (quality.empty()) return;
    TimingQuality all;
    std::string disturbed;
    bool first = true;
    for (const auto& [name, q] : quality) {
        all = first ? q : (all += q);
        first = false;
        if (!q.clean()) disturbed += (disturbed.empty() ? "" : ", ") + name;
    }
    if (totals.timing_id().empty()) all.load_end = load_average();  // a shared timing's loads are its own
    out << "software timing (thread CPU time" << (totals.timing_id().empty() ? "" : ", shared " + totals.timing_id())
        << "): " << all.describe(totals.retime_tries());
    if (!disturbed.empty()) out << "; " << disturbed << "'s speedup may not hold (docs/timing.md)";
    out << '\n';
    const bool pinned = run.settings != nullptr && run.settings->settings().run.pinned_cpu().has_value();
    const std::string advice = all.advice(totals.retime_tries(), pinned, read_machine_info().cores_online);
    if (!advice.empty()) out << "  " << advice << '\n';
}

// The board's energy a frame by part and a pair, and each baseline's on
// the host beside it (docs/energy.md); nothing where no power is stated.
void print_energy(std::ostream& out, const RunDescription& run, const RunTotals& totals) {
    const ReportSummary s = totals.summary(run.host_timing);
    const FrameEnergy& e = s.mean_energy;
    if (e.total_j() <= 0 && s.host_package_w <= 0) return;
    char line[512];
    std::snprintf(line, sizeof line,
                  "  energy: %.4g mJ a frame (static %.4g, dynamic %.4g, bus %.4g, host %.4g), %.4g uJ a pair\n",
                  e.total_j() * 1e3, e.static_j * 1e3, e.dynamic_j * 1e3, e.bus_j * 1e3, e.host_j * 1e3,
                  s.mean_energy_per_pair_j * 1e6);
    out << line;
    for (const auto& [name, b] : s.baselines) {
        std::snprintf(line, sizeof line, "  energy: %s %.4g mJ a frame on the host at its stated %.4g W, %.3gx the board's\n",
                      name.c_str(), b.energy_j * 1e3, s.host_package_w, b.energy_ratio);
        out << line;
        if (b.native_energy_j >= 0) {
            std::snprintf(line, sizeof line, "          this machine's package, measured by RAPL: %.4g mJ a frame\n",
                          b.native_energy_j * 1e3);
            out << line;
        }
    }
}

// The software the board is held to: the fastest baseline timed.
void print_fastest(std::ostream& out, const ReportSummary& summary) {
    if (summary.best_software.empty() || summary.baselines.size() < 2) return;
    const BaselineSummary& best = summary.baselines.at(summary.best_software);
    char line[256];
    std::snprintf(line, sizeof line,
                  "fastest software: %s, %.1f us a frame on the host; the board's speedup over it %.2fx, energy "
                  "ratio %.3gx (its energy a frame over the board's)\n",
                  summary.best_software.c_str(), best.host_ns.mean / 1e3, best.speedup, best.energy_ratio);
    out << line;
}

// The means the speedups are taken from, with p50, p99 and the maximum.
void print_timing(std::ostream& out, const RunDescription& run, const RunTotals& totals) {
    if (totals.frames() == 0) return;
    const TimingFigures board = totals.board_figures();
    const std::map<std::string, TimingFigures> baselines = totals.baseline_figures();
    char line[512];
    out << "\nper frame, mean of " << frames_described(totals, board);
    if (!baselines.empty()) {
        out << "; software on host " << printable(run.host) << ": " << run.host_timing.describe();
        if (run.baseline_runs > 1) out << ", timed in " << run.baseline_runs << " runs (median of their means)";
    }
    const Spread& b = board.spread;
    std::snprintf(line, sizeof line,
                  ":\n  board: %.1f us (p50 %.1f, p99 %.1f, max %.1f), simulated: the same on every run\n",
                  b.mean / 1e3, b.p50 / 1e3, b.p99 / 1e3, b.max / 1e3);
    out << line;
    if (run.config.box_banks > 1) {
        const Spread latency = totals.latency_figures().spread;
        std::snprintf(line, sizeof line,
                      "  pipelined (two box banks): the board's time is the host's a frame; latency from upload to "
                      "pairs %.1f us (p50 %.1f, max %.1f)\n",
                      latency.mean / 1e3, latency.p50 / 1e3, latency.max / 1e3);
        out << line;
    }
    print_energy(out, run, totals);
    const Spread wall = totals.sim_wall_figures().spread;
    std::snprintf(line, sizeof line, "  simulator: %.3f ms native wall time (p50 %.3f, p99 %.3f, max %.3f)\n",
                  wall.mean / 1e6, wall.p50 / 1e6, wall.p99 / 1e6, wall.max / 1e6);
    out << line;
    if (!baselines.empty()) {
        // The names' column is as wide as the longest (fcl_interval, ode_quadtree).
        int width = 8;
        for (const auto& entry : baselines) width = std::max(width, static_cast<int>(entry.first.size()));
        out << "      N    m   board_us  " << std::string("software").append(width - 8, ' ')
            << "  factor  mean_host_us   p50_host_us   p99_host_us   max_host_us  speedup\n";
        for (const auto& [name, figures] : baselines) {
            const double factor = run.host_timing.factor(name);
            const Spread sw = figures.spread.scaled(factor);
            std::snprintf(line, sizeof line, "%7llu %4u %10.1f  %-*s %7.3g %13.1f %13.1f %13.1f %13.1f %7.2fx\n",
                          static_cast<unsigned long long>(totals.last_objects()), run.config.m, b.mean / 1e3,
                          width, name.c_str(), factor, sw.mean / 1e3, sw.p50 / 1e3, sw.p99 / 1e3, sw.max / 1e3,
                          speedup(sw, b));
            out << line;
        }
        print_fastest(out, totals.summary(run.host_timing));
        print_timing_quality(out, run, totals);
    }
    if (board.too_few_frames()) {
        out << "note: these figures rest on " << frames_text(board.frames_per_run) << ", fewer than " << kMinMeasuredFrames
            << ": one disturbed frame moves a mean by a tenth of its excess, and p99 is the maximum; give --frames "
            << totals.warmup_frames() + kMinMeasuredFrames << " or more\n";
    }
}

}  // namespace

void print_summary(std::ostream& out, const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall) {
    const BoardConfig& c = run.config;
    char line[512];
    // Names may be long and come from files: printed whole and escaped.
    std::snprintf(line, sizeof line, ": m=%u (%u %s lanes), %.6g MHz, L=%u cycles, %u block RAMs for the %s, %s %s\n", c.m,
                  c.lanes(), c.format.name().c_str(), c.clock_mhz, c.pipeline_latency(), run.block_rams,
                  c.grid_board() ? "cell buffer" : "boxes", name_of(run.fidelity),
                  run.fidelity == ModelLevel::kAnalytic ? "level" : "engine");
    out << printable(run.source) << " on " << printable(run.board) << " (" << printable(run.bus) << ")" << line;
    if (run.device_fit) print_resources(out, *run.device_fit);
    // A clock beyond the estimate, run anyway: said where the estimate is.
    if (!totals.timing_warning().empty()) out << "  warning: " << totals.timing_warning() << '\n';
    if (run.ssram) {
        std::snprintf(line, sizeof line,
                      "  boxes in SSRAM: %u tiles of %u boxes at %u objects, %llu slots waiting for tile loads\n",
                      run.tiles, c.tiles.boxes, run.capacity, static_cast<unsigned long long>(run.load_wait_slots));
        out << line;
    }
    if (c.grid_board()) {
        std::snprintf(line, sizeof line,
                      "  grid board: %u cells a side at %u objects, cells of %u boxes, spans of %u cells (docs/grid_board.md)\n",
                      c.grid.dims_for(run.capacity), run.capacity, c.grid.cell_capacity, c.grid.max_span);
        out << line;
    }
    // A grid board's slots depend on its boxes: its frames show the slots it took.
    out << (c.grid_board() ? "  frame  objects     pairs   slots+L" : "  frame  objects     pairs  S(N,m)+L")
        << "  compute_cycles  stall_cycles  compute_us  total_us\n";
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
        const uint64_t more = totals.frames() - totals.shown().size();
        out << "    ... (" << more << (more == 1 ? " more frame" : " more frames")
            << (run.has_report ? " in the report)\n" : "; --report FILE lists every frame)\n");
    }
    std::snprintf(line, sizeof line, "total: %s, %llu pairs, %llu board cycles (%llu stalled)\n",
                  frames_text(totals.frames()).c_str(), static_cast<unsigned long long>(totals.pairs()),
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
    // The simulator's own time (each frame on the platform), apart from the
    // software baselines timed beside it.
    const double rate = wall.simulator_s > 0 ? static_cast<double>(totals.cycles()) / wall.simulator_s : 0.0;
    std::snprintf(line, sizeof line, "simulated in %.3f s of native wall time (%.2f M board cycles/s)", wall.simulator_s,
                  rate / 1e6);
    out << line;
    if (wall.baselines_s > 0) {
        std::snprintf(line, sizeof line, "; the software baselines took %.3f s", wall.baselines_s);
        out << line;
    }
    out << "\n";
}

}  // namespace cdvp
