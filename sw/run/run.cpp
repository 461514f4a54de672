#include "sw/run/run.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "models/common/user_text.h"
#include "platform/fault_injection.h"
#include "sw/bullet/scenes.h"
#include "sw/run/best_software.h"
#include "sw/run/bullet_scene_source.h"
#include "sw/run/bullet_worlds.h"
#include "sw/run/exit_codes.h"
#include "sw/run/generated_source.h"
#include "sw/run/run_checks.h"
#include "sw/run/run_frames.h"
#include "sw/run/run_memo.h"

namespace cdvp {

const char* command_of(const RunSpec& spec) {
    return spec.frames && std::holds_alternative<BulletWorlds>(*spec.frames) ? "bullet" : "run";
}

namespace {

// The generated scene's name, empty for a trace.
std::string scene_name(const RunSpec& spec) {
    if (const auto* scene = std::get_if<SceneFrames>(&*spec.frames)) return scene->name;
    if (const auto* worlds = std::get_if<BulletWorlds>(&*spec.frames)) return worlds->name;
    return {};
}

// What the analytic level cannot model is refused, not silently ignored.
void check_analytic_run(const RunSetup& setup, const RunSpec& spec) {
    const SettingValues& values = setup.values;
    const SettingNames& names = values.names();
    const Setting& fidelity = declared_setting("run.fidelity");
    const std::string level =
        std::string("the ") + name_of(values.settings().run.fidelity) + " level (" + values.where(fidelity) + ")";
    if (!spec.faults.empty()) {
        throw InputError(names.input("inject") + ": " + level + " has no engine to inject faults into; use " +
                         names.setting_to(fidelity, "fast") + " or cycle");
    }
}

unsigned run_baseline_threads(const Settings& settings) {
    return baseline_threads(settings.run.threads, settings.host.cores);
}

BaselineTimer baseline_timer(const RunSpec& spec, const RunSetup& setup, std::optional<std::size_t> objects) {
    const Settings& settings = setup.values.settings();
    const unsigned threads = run_baseline_threads(settings);
    // Each name is timed once a frame, best's candidates as any other.
    if (std::count(spec.baselines.begin(), spec.baselines.end(), kBestSoftware) > 1) {
        throw InputError(spec.settings.names->input("baseline") + ": '" + kBestSoftware + "' given twice");
    }
    return BaselineTimer(resolve_baselines(spec.baselines, objects, threads), setup.host, settings.run.retime_tries,
                         spec.settings.names->input("baseline"),
                         BaselineOptions{threads, setup.values.where(declared_setting("run.threads"))});
}

// "best" for the frames at hand: the candidates for their largest frame.
void resolve_best(const RunSpec& spec, RunSetup& setup, const FrameSource& source) {
    if (asks_for_best(spec.baselines)) setup.baselines = baseline_timer(spec, setup, source.max_objects());
}

RunSetup make_setup(const RunSpec& spec) {
    const SettingNames& names = *spec.settings.names;
    RunSetup setup;
    // The settings' own checks first, as cdvp settings makes them.
    static_cast<BoardSetup&>(setup) = checked_board_setup(spec.settings, scene_name(spec));
    setup.platform.faults = fault_specs(spec.faults, setup.platform.driver, names);
    setup.level = model_level(setup.values, spec.outputs.waves.has_value());
    setup.platform.fidelity = engine_of(setup.level, setup.values.settings().run.lockstep);
    if (setup.level == ModelLevel::kAnalytic || setup.level == ModelLevel::kAuto) check_analytic_run(setup, spec);
    // Pipelined frames must be known ahead; an application's next frame
    // comes from this frame's pairs (a kinematic family's does not).
    if (const auto* scene = std::get_if<SceneFrames>(&*spec.frames);
        scene && !is_kinematic_scene(scene->name) && setup.values.settings().board.box_banks > 1) {
        throw InputError(setup.values.where(declared_setting("board.box_banks")) + ": two box banks pipeline frames, but " +
                         names.input("scene") + " " + scene->name + " steps on each frame's pairs, so its next frame is " +
                         "not known ahead; expected " + names.input("trace") +
                         " (cdvp record writes a scene's frames to one)");
    }
    setup.trace_window = vcd_window(spec.outputs.waves ? spec.outputs.waves->frames : std::nullopt, names);
    // "best" as every candidate for now (the budgets hold all of them); the
    // frames' size decides once they are open (resolve_best).
    setup.baselines = baseline_timer(spec, setup, std::nullopt);
    const Setting& repeat = declared_setting("run.repeat");
    if (!setup.values.is_default(repeat) && setup.baselines.empty()) {
        throw InputError(setup.values.where(repeat) + ": reruns the software baselines over the frames; give " +
                         names.input("baseline") + " too");
    }
    return setup;
}

std::unique_ptr<FrameSource> open_source(const RunSpec& spec, const SettingValues& values, const RunBudgets& budgets,
                                         RunMemo* memo) {
    if (const auto* trace = std::get_if<TraceFrames>(&*spec.frames)) {
        return trace_source(trace->path, budgets.trace_limits(), budgets.input_limits());
    }
    const Settings& settings = values.settings();
    const std::string scene = scene_name(spec);
    if (is_bullet_scene(scene)) {
        return bullet_scene_source(bullet_scene_spec(scene, values), static_cast<std::size_t>(settings.scene.frames));
    }
    return generated_source(scene, values, memo != nullptr ? &memo->scenes : nullptr);
}

// A run of a trace's frames or a generated scene's.
RunOutcome run_frames_of(const RunSpec& spec, RunObserver& observer, const RunContext& context) {
    const SettingNames& names = *spec.settings.names;
    check_frame_input(spec.frames, names);
    RunSetup setup = make_setup(spec);
    const bool needs_kernel = context.kernel_free && setup.level != ModelLevel::kAnalytic;
    if (needs_kernel && !context.check_first) return RunOutcome{false, 0, {}};
    // Outputs next (the level says what the waveforms hold): a path that
    // cannot be written, or that names an input or another output, is
    // refused before any work. A run only checked here for a child opens
    // none: the child writes them.
    RunFiles files;
    if (!needs_kernel) open_run_files(spec, setup.level, files);
    const bool trace = std::holds_alternative<TraceFrames>(*spec.frames);
    check_scene_settings(trace, setup.values);
    const FrameOrigin origin = trace ? FrameOrigin{std::get<TraceFrames>(*spec.frames).path, ""}
                                     : FrameOrigin{"", scene_name(spec)};
    RunBudgets budgets(setup.values, setup.platform, budget_shape(spec, setup), origin);
    // A generated scene is checked before it is generated (millions of
    // spheres take a while to place), a trace once it is read.
    const SceneSettings& scene = setup.values.settings().scene;
    if (!trace) {
        // A Bullet scene's board holds its every collision object.
        const uint64_t boxes = is_bullet_scene(origin.scene)
                                   ? scene_layout(bullet_scene_spec(origin.scene, setup.values)).proxies
                                   : scene.objects;
        check_scene_fits(origin, setup.values, boxes, scene.frames, budgets);  // its warning comes below
        const std::optional<uint64_t> last = scene.frames > 0 ? std::optional<uint64_t>(scene.frames - 1) : std::nullopt;
        check_inject_frames(setup.platform.faults, last, [](uint64_t) { return true; },
                            setup.values.names().setting_to(declared_setting("scene.frames"), std::to_string(scene.frames)), names);
    }
    if (needs_kernel) return RunOutcome{false, 0, {}};  // checked first: the child reads the frames
    std::unique_ptr<FrameSource> source = open_source(spec, setup.values, budgets, context.memo);
    setup.clock_warning = check_scene_fits(origin, setup.values, source->max_objects(), source->frame_count(), budgets);
    if (setup.clock_warning) observer.note("warning: " + *setup.clock_warning);
    check_inject_frames(setup.platform.faults, source->last_frame(),
                        [&source](uint64_t n) { return source->has_frame(n); }, source->describe(), names);
    check_trace_window(setup.trace_window, source->last_frame(), source->describe(), names);
    resolve_best(spec, setup, *source);
    pin_to_setting_cpu(setup.values);
    std::optional<SharedBaselines> shared;
    if (spec.software_timings && !setup.baselines.empty()) {
        if (spec.software_timings->empty()) {
            throw InputError(names.input("software-timings") + ": expected a directory, got ''");
        }
        shared.emplace(*spec.software_timings, names.input("software-timings"),
                       software_workload(scene_name(spec), *source, setup.values, setup.baselines.names(), setup.host),
                       setup.baselines.names(), setup.values.settings().run.repeat, source->frame_count());
    }
    // Every stage that collects a frame's pairs holds the same budget.
    setup.platform.pair_budget = budgets.pair_budget();
    setup.baselines.set_pair_budget(budgets.pair_budget());
    if (context.memo != nullptr) setup.platform.pair_memo = context.memo->pairs;
    FrameRun frames{spec, *source, setup, files, budgets, observer, context, shared ? &*shared : nullptr};
    return run_frames(frames);
}

RunOutcome checked_run(const RunSpec& spec, RunObserver& observer, const RunContext& context) {
    const SettingNames& names = *spec.settings.names;
    std::optional<std::string> trace;
    if (const auto* t = spec.frames ? std::get_if<TraceFrames>(&*spec.frames) : nullptr) trace = t->path;
    const std::optional<std::string> vcd = spec.outputs.waves ? std::optional(spec.outputs.waves->path) : std::nullopt;
    check_path_lengths({{"trace", &trace},
                        {"board", &spec.settings.board},
                        {"config", &spec.settings.config},
                        {"pairs-out", &spec.outputs.pairs_csv},
                        {"report", &spec.outputs.report},
                        {"vcd", &vcd}},
                       names);
    if (spec.frames && std::holds_alternative<BulletWorlds>(*spec.frames)) {
        if (context.kernel_free) return RunOutcome{false, 0, {}};
        return run_bullet_worlds(spec, observer);
    }
    return run_frames_of(spec, observer, context);
}

}  // namespace

RunOutcome run(const RunSpec& spec, RunObserver& observer, const RunContext& context) {
    try {
        return checked_run(spec, observer, context);
    } catch (const std::exception&) {
        const Failure failure = failure_of_current_exception();
        return RunOutcome{true, failure.status, failure.message};
    }
}

}  // namespace cdvp
