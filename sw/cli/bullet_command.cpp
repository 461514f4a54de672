#include "sw/cli/bullet_command.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "models/common/user_text.h"
#include "sw/bullet/board_broadphase.h"
#include "sw/cli/bullet_report.h"
#include "sw/cli/machine_info.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/format_reference.h"
#include "sw/cli/run_checks.h"
#include "sw/cli/run_setup.h"
#include "sw/cli/wave_outputs.h"
#include "sw/timing/speed_probe.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kUsage =
    "Usage: cdvp bullet --scene NAME [--objects N] [--frames F] [--seed S] [--board B] [options]\n"
    "\n"
    "Steps a Bullet scene (btDiscreteDynamicsWorld) with the virtual board as its broad phase and, in\n"
    "lockstep, the same scene on one of Bullet's broad phases. Per frame: the board's modelled time,\n"
    "Bullet's broad-phase time (AABB update and pair search) and whole step time, the broad phase's\n"
    "share of the step and its Amdahl bound (the most any broad-phase accelerator can speed the step\n"
    "up), and the speed-ups the board gives. Software times are the thread's CPU time x the host factor\n"
    "(from the host profile, as for cdvp run: docs/timing.md); a step a pre-emption or a move to another\n"
    "CPU disturbed is stepped again on a fresh world and timed again (--retime-tries). The summary gives\n"
    "each time's mean over the frames after the warm-up, which the speed-ups compare, with p50, p99 and\n"
    "the maximum, and whether the software's timing came clean.\n"
    "Settings come in layers, each over the last, as for cdvp run: defaults < --board preset\n"
    "< --config FILE < -c NAME=VALUE < the dedicated flags below; the board is checked against its\n"
    "device as cdvp run checks it (--memory auto moves the boxes to SSRAM tiles past the block RAMs).\n"
    "The report is cdvp run's, with a 'bullet' section for the Bullet worlds' times (docs/bullet.md).\n"
    "Options are spelt in full (no abbreviations); numbers show their range and default";

struct BulletOptions {
    std::string scene;
    SettingLayers layers;
    std::string software = "dbvt";
    std::string report, vcd, vcd_frames, vcd_format = "vcd";
    bool quiet = false;
};

// Every setting means to a Bullet world on the board what it means to a run,
// but the trace's size limit: no trace is read.
bool applies_to_bullet(const Setting& s) { return s.name != "run.max_trace_size"; }

po::options_description bullet_options(BulletOptions& o) {
    po::options_description scene("Scene");
    const std::string scenes = bullet_scene_help() + "; each is built around its own number of bodies (" +
                               bullet_scene_defaults() + ") unless --objects says otherwise";
    scene.add_options()("scene", po::value(&o.scene)->value_name("NAME"), scenes.c_str());
    add_setting_flags(scene, {"scene"}, o.layers.flags);
    po::options_description board("Board");
    add_board_option(board, o.layers.board_name);
    add_setting_flags(board, {"board"}, o.layers.flags);
    po::options_description host("Host and software");
    host.add_options()
        ("software", po::value(&o.software)->value_name("simple|sap|dbvt")->default_value(o.software),
         "Bullet's broad phase to compare with: btSimpleBroadphase, btAxisSweep3, btDbvtBroadphase");
    add_setting_flags(host, {"host", "driver", "run"}, o.layers.flags, false, applies_to_bullet);
    po::options_description budgets("Budgets (checked before the work, and the pairs as they are found; docs/numerics.md)");
    add_setting_flags(budgets, {"run"}, o.layers.flags, true, applies_to_bullet);
    po::options_description output("Output (written only if the whole run succeeds)");
    output.add_options()
        ("report", po::value(&o.report)->value_name("FILE"),
         "JSON report: cdvp run's (every setting with where it came from, the board's phases and cycles a "
         "frame, the summary) and a 'bullet' section (the worlds' times, share, Amdahl bound, gains)");
    add_wave_options(output, o.vcd, o.vcd_frames, o.vcd_format);
    output.add_options()("quiet,q", po::bool_switch(&o.quiet), "print nothing but errors");
    po::options_description all = scene;
    all.add(board).add(settings_options(o.layers)).add(host).add(budgets).add(output);
    return all;
}

// The run's output files: one transaction (see OutputSet).
struct Outputs {
    OutputSet files;
    OutputFile* report = nullptr;
    WaveOutputs waves;
};

void open_outputs(const BulletOptions& o, const po::variables_map& vm, Outputs& out) {
    add_setting_inputs(out.files, o.layers, vm);
    std::optional<std::size_t> report;
    if (vm.count("report")) report = out.files.add_output("--report", o.report);
    open_with_waves_and_summary(out.files, out.waves, vm, o.vcd, o.vcd_format, o.quiet);
    if (report) out.report = &out.files.file(*report);
}

struct Setup : BoardSetup {
    BroadphaseKind software = BroadphaseKind::kDbvt;
    std::pair<uint64_t, uint64_t> trace_window{0, UINT64_MAX};  // --vcd-frames
};

Setup make_setup(const BulletOptions& o, const po::variables_map& vm) {
    Setup setup;
    static_cast<BoardSetup&>(setup) = board_setup(o.layers, vm, o.scene);
    setup.level = model_level(setup.values, vm);
    if (setup.level == ModelLevel::kAnalytic) {
        throw InputError(setup.values.where(*find_setting("run.fidelity")) +
                         " analytic: cdvp bullet runs Bullet's world on the platform's engines; expected cycle or fast");
    }
    if (setup.values.settings().board.box_banks > 1) {
        throw InputError(setup.values.where(*find_setting("board.box_banks")) +
                         ": two box banks pipeline frames, but a Bullet world steps on each frame's pairs, so its next "
                         "frame is not known ahead; expected 1 (cdvp record, then cdvp run --trace, pipelines its frames)");
    }
    setup.platform.fidelity = engine_of(setup.level, setup.values.settings().run.lockstep);
    setup.trace_window = vcd_window(o.vcd_frames, vm);
    // Bullet's times are whole worlds, not the reference workload's
    // baselines: they all take the overall factor.
    setup.host = resolve_host_timing(setup.values);
    if (o.software != "simple" && o.software != "sap" && o.software != "dbvt") {
        throw InputError("--software: expected simple, sap or dbvt, got '" + excerpt(o.software) + "'");
    }
    setup.software = broadphase_kind(o.software);
    return setup;
}

// What the budgets see: the board's world and the software's beside it.
RunShape bullet_shape(const Setup& setup) {
    RunShape shape;
    shape.clocked = setup.platform.fidelity == Fidelity::kCycle;
    shape.board = setup.platform.board;
    shape.bullet_worlds = 2;
    return shape;
}

// A frame the board could not finish: past the pair budget or the simulated
// time limit (bad input), or a fault of the simulated system.
int frame_failed(const FrameFault& fault, uint64_t frame, const RunBudgets& budgets) {
    if (fault.kind == FrameFault::Kind::kPairBudget) {
        throw InputError(budgets.pair_budget_refusal(frame, fault.pairs_found));
    }
    std::cerr << "cdvp bullet: frame " << frame << ": " << printable(fault.message) << '\n';
    return fault.kind == FrameFault::Kind::kDevice ? kExitDeviceFault : kExitBadInput;
}

// A fixed-point board's pairs hold every pair of the float32 reference (the
// run checks it, as cdvp run does); the extra ones reach Bullet's cache,
// whose narrow phase finds them apart.
std::optional<std::string> lost_pair(const FormatReference::Check& check, NumberFormat format, uint32_t boxes) {
    if (!check.missing) return std::nullopt;
    Frame frame;  // the board's order is the world's: ids are board indices
    frame.ids.resize(boxes);
    std::iota(frame.ids.begin(), frame.ids.end(), uint64_t{0});
    return lost_pair_message(format, frame, *check.missing);
}

// A software step with a speed probe before and after it: the slower in `slower`.
StepTimes probed_step(BulletWorld& world, SpeedProbe& probe, double& slower) {
    const double before = probe.time_ns();
    const StepTimes step = world.step();
    slower = std::max(before, probe.time_ns());
    return step;
}

// Each software step after the warm-up that a pre-emption or a move to
// another CPU disturbed is timed again: a fresh world stepped untimed up to
// it (Bullet's worlds are deterministic), up to `tries` passes. The quality
// of the software world's timing, its loads left for the caller.
TimingQuality retime_software(const SceneSpec& spec, BroadphaseKind software, double factor, uint32_t tries,
                              double probe_reference_ns, std::vector<std::vector<bool>>& disturbed,
                              const std::vector<std::vector<double>>& probes, SpeedProbe& probe, BulletTimes& times) {
    const std::size_t frames = disturbed.empty() ? 0 : disturbed[0].size();
    const std::size_t first = frames > times.warmup_frames() ? times.warmup_frames() : 0;
    TimingQuality quality;
    // A step on a slowed CPU (its probes slower than the machine's fast speed) is disturbed too.
    std::vector<double> all;
    for (const std::vector<double>& run : probes) all.insert(all.end(), run.begin() + static_cast<std::ptrdiff_t>(first), run.end());
    quality.probe_ns = probe_reference_ns > 0 ? probe_reference_ns : fast_probe_ns(all);
    const double limit = quality.probe_ns * (1 + kProbeTolerance);
    for (std::size_t run = 0; run < disturbed.size(); ++run) {
        for (std::size_t k = first; k < frames; ++k) {
            if (disturbed[run][k] || probes[run][k] <= limit) continue;
            disturbed[run][k] = true;
            ++quality.frames_slowed;
        }
    }
    for (uint32_t pass = 0; pass < tries; ++pass) {
        bool any = false;
        for (std::size_t run = 0; run < disturbed.size(); ++run) {
            std::size_t last = frames;
            for (std::size_t k = first; k < frames; ++k) {
                if (disturbed[run][k]) last = k;
            }
            if (last == frames) continue;
            any = true;
            const std::unique_ptr<BulletWorld> world = make_scene_world(spec, software);
            for (std::size_t k = 0; k <= last; ++k) {
                if (k < first || !disturbed[run][k]) {
                    world->step();
                    continue;
                }
                double slower = 0;
                const StepTimes step = probed_step(*world, probe, slower);
                ++quality.tries;
                if (step.disturbed || slower > limit) continue;
                times.replace_software(run, k, step.broadphase_share_ns() * factor, step.step_ns * factor);
                disturbed[run][k] = false;
                ++quality.frames_retimed;
            }
        }
        if (!any) break;
    }
    for (const std::vector<bool>& flags : disturbed) {
        for (std::size_t k = first; k < flags.size(); ++k) {
            ++quality.frames_timed;
            quality.never_clean += flags[k] ? 1 : 0;
        }
    }
    quality.frames_disturbed = quality.frames_retimed + quality.never_clean;
    quality.runs = static_cast<uint32_t>(disturbed.size());
    quality.repeat_spread = repeat_spread_of(times.figures(&BulletFrame::software_step_host_ns).run_means);
    return quality;
}

int step_worlds(const BulletOptions& o, const SceneSpec& spec, Setup& setup, Outputs& out, const RunBudgets& budgets,
                const std::vector<std::string>& command_line) {
    const uint32_t boxes = scene_layout(spec).proxies;
    RunConfig run = describe_run(setup, boxes, budgets);
    describe_device_fit(run, setup.values.settings());
    run.source = describe(spec);
    run.command_line = command_line;
    run.has_report = out.report != nullptr;
    const Settings& settings = setup.values.settings();
    const double factor = setup.host.overall;
    VirtualBoard platform("platform", setup.platform, boxes, out.waves.trace_base());
    run.bus = platform.bus_timing().describe();
    platform.set_trace_window(setup.trace_window.first, setup.trace_window.second);
    PlatformLink link(platform, boxes);
    auto board_world = make_scene_world(spec, BroadphaseKind::kBoard, &link);
    auto software_world = make_scene_world(spec, setup.software);
    const auto& broadphase = dynamic_cast<const BoardBroadphase&>(board_world->broadphase());
    std::optional<ReportWriter> report;
    if (out.report) {
        report.emplace(out.report->stream());
        report->begin(run);
    }
    RunTotals totals(settings.run.warmup);
    BulletTimes times(settings.run.warmup);
    FormatReference reference(run.config.format, setup.platform.driver.ns_per_pair, budgets.pair_budget());
    RunWallTimes wall;  // the board's simulation, and the software worlds' steps beside it
    std::vector<std::vector<bool>> disturbed(1);  // the software world's steps, [run][frame]
    std::vector<std::vector<double>> probes(1);   // the slower speed probe beside each
    SpeedProbe probe;
    for (uint64_t frame = 0; frame < settings.scene.frames; ++frame) {
        StepTimes board_step;
        try {
            board_step = board_world->step();
        } catch (const BoardFrameFault&) {
            return frame_failed(link.last_fault(), frame, budgets);
        }
        double slower = 0;
        const StepTimes software_step = probed_step(*software_world, probe, slower);
        disturbed[0].push_back(software_step.disturbed);
        probes[0].push_back(slower);
        const BoardFrameStats& board = broadphase.last_frame();
        wall.simulator_s += board.simulate_ns * 1e-9;
        wall.baselines_s += software_step.step_ns * 1e-9;
        const FrameResult& result = *link.last_result();
        FormatReference::Check check;
        try {
            check = reference.check(broadphase.last_boxes(), result.pairs, result.phases);
        } catch (const PairBudgetExceeded& e) {
            throw InputError(budgets.pair_budget_refusal(frame, e.found()));
        }
        if (const std::optional<std::string> lost = lost_pair(check, run.config.format, board.proxies)) {
            std::cerr << "cdvp bullet: frame " << frame << ": " << *lost << '\n';
            return kExitDeviceFault;
        }
        const FrameStats stats{frame, board.proxies, board.board_pairs,
                               run.config.swept_slots(board.proxies, board.phases.compute_cycles,
                                                      board.phases.stall_cycles),
                               load_wait_slots(run, board.proxies), board.phases, {}, board.simulate_ns, check.extra};
        if (report) report->frame(stats);
        totals.add(stats);
        times.add({frame, board.proxies, board.board_pairs, board_world->contact_points(), board.phases.total_ns,
                   (board_step.aabbs_ns + board.bookkeeping_ns) * factor, software_step.broadphase_share_ns() * factor,
                   software_step.step_ns * factor});
    }
    // The later runs step a fresh software world from the same start: the
    // board's times are simulated, the same every run.
    for (uint32_t repeat = 2; repeat <= settings.run.repeat; ++repeat) {
        software_world.reset();  // its memory is not the fresh world's to reuse
        software_world = make_scene_world(spec, setup.software);
        times.start_software_run();
        disturbed.emplace_back();
        probes.emplace_back();
        for (uint64_t frame = 0; frame < settings.scene.frames; ++frame) {
            double slower = 0;
            const StepTimes step = probed_step(*software_world, probe, slower);
            probes.back().push_back(slower);
            wall.baselines_s += step.step_ns * 1e-9;
            times.add_software(step.broadphase_share_ns() * factor, step.step_ns * factor);
            disturbed.back().push_back(step.disturbed);
        }
    }
    software_world.reset();
    const auto retime_start = std::chrono::steady_clock::now();
    TimingQuality quality = retime_software(spec, setup.software, factor, settings.run.retime_tries,
                                            setup.host.probe_reference_ns, disturbed, probes, probe, times);
    wall.baselines_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - retime_start).count();
    quality.load_start = run.load_average_start;
    quality.load_end = load_average();
    times.set_quality(quality, settings.run.retime_tries);
    platform.close_trace();
    if (const std::optional<std::string> failed = out.waves.finish(platform)) {
        std::cerr << "cdvp bullet: " << *failed << '\n';
        return kExitSystem;
    }
    if (report) {
        const nlohmann::json bullet = {{"bullet", times.section(spec, setup.software)}};
        report->end(totals, setup.host, &bullet);
    }
    if (!o.quiet) {
        std::ostringstream summary;
        print_summary(summary, run, totals, wall);
        summary << times.table(setup.software, run.host, setup.host.describe(), run.has_report);
        out.files.set_standard_output(summary.str());
    }
    if (const std::optional<OutputFailure> failure = out.files.try_commit()) return commit_failed("cdvp bullet", *failure);
    const std::string note = uncalibrated_note(setup.host);
    if (!o.quiet && !note.empty()) std::cerr << "cdvp bullet: " << note << '\n';
    return kExitDone;
}

int simulate(const BulletOptions& o, const po::variables_map& vm, const std::vector<std::string>& command_line) {
    check_path_lengths({{"board", &o.layers.board_name}, {"config", &o.layers.config}, {"report", &o.report},
                        {"vcd", &o.vcd}},
                       vm);
    // Outputs first: a path that cannot be written, or that names an input
    // or another output, is refused before any work.
    Outputs out;
    open_outputs(o, vm, out);
    if (vm.count("scene") == 0) throw InputError("--scene: expected one of " + bullet_scene_list());
    check_bullet_scene_name(o.scene);
    Setup setup = make_setup(o, vm);
    const SettingValues& values = setup.values;
    const SceneSpec spec = bullet_scene_spec(o.scene, values);
    const uint64_t frames = values.settings().scene.frames;
    if (frames == 0) {
        throw InputError(values.where(*find_setting("scene.frames")) + ": expected at least 1 frame to step, got 0");
    }
    const FrameOrigin origin{"", o.scene};
    RunBudgets budgets(values, setup.platform, bullet_shape(setup), origin);
    check_scene_fits(origin, values, scene_layout(spec).proxies, frames, budgets);
    check_trace_window(setup.trace_window, frames - 1, describe(spec));
    setup.platform.pair_budget = budgets.pair_budget();
    pin_to_setting_cpu(values);
    return step_worlds(o, spec, setup, out, budgets, command_line);
}

}  // namespace

int bullet_command(int argc, char** argv) {
    BulletOptions o;
    const po::options_description options = bullet_options(o);
    return run_command_line("cdvp bullet", argc, argv, kUsage, options, [&](const po::variables_map& vm) {
        return simulate(o, vm, report_command_line(argc, argv));
    });
}

}  // namespace cdvp
