#include "sw/run/run_setup.h"

#include "sw/timing/thread_timer.h"

#include "platform/settings/board_preset.h"
#include "platform/settings/config_file.h"
#include "platform/device_fit.h"
#include "platform/memory_plan.h"
#include "platform/platform_settings.h"
#include "sw/bullet/scenes.h"
#include "sw/run/generated_source.h"

namespace cdvp {

namespace {

// A value given typed went through no parser of ours (a Python keyword, a
// program's own RunSpec): it is held to its setting's type and range here,
// and comes back as the setting's own kind of value (a whole number for a
// real setting is a real).
SettingValue checked_given(const Assignment& given, const SettingNames& names) {
    const Setting& s = *given.setting;
    try {
        if (const auto* count = std::get_if<uint64_t>(&given.value)) return s.from_count(*count);
        if (const auto* real = std::get_if<double>(&given.value)) return s.from_number(*real, to_text(given.value));
        return s.from_string(std::get<std::string>(given.value));
    } catch (const std::invalid_argument& e) {
        throw InputError(names.given(s) + ": " + e.what());
    }
}

// The grid's settings set nothing on the all-pairs board: one the user gave
// (a preset may carry them for either board) is refused, as a bus's setting
// on another bus is, so that a run or a sweep axis never changes nothing in silence.
void refuse_grid_settings_on_all_pairs(const SettingValues& values) {
    if (values.settings().board.grid_board()) return;
    const Setting& algorithm = *find_setting("board.algorithm");
    for (const Setting* s : values.effective()) {
        if (s->name.rfind("board.grid.", 0) != 0) continue;
        const SettingOrigin::Kind kind = values.origin(*s).kind;
        if (kind == SettingOrigin::Kind::kDefault || kind == SettingOrigin::Kind::kPreset) continue;
        throw InputError(values.where(*s) + ": a setting of the grid board; the board is all_pairs (" +
                         (values.is_default(algorithm) ? std::string("the default") : values.where(algorithm)) +
                         "): give " + values.names().setting_to(algorithm, "grid"));
    }
}

}  // namespace

SettingValues layered_settings(const SettingLayers& layers, const std::string& scene, std::string& board_name) {
    const SettingNames& names = *layers.names;
    SettingValues values(layers.names);
    if (is_bullet_scene(scene)) {
        // Still the default: every layer above says otherwise.
        values.apply({{find_setting("scene.objects"), uint64_t{default_objects(scene)}, {}}});
    }
    if (layers.board) {
        if (layers.board->empty()) throw InputError(names.input("board") + ": expected a preset name or a .json path, got ''");
        const std::shared_ptr<const BoardPreset> preset = load_shared_board_preset(*layers.board, names.input("board"));
        values.apply(preset->values);
        board_name = preset->name;
    }
    if (layers.config) {
        if (layers.config->empty()) throw InputError(names.input("config") + ": expected a file path, got ''");
        values.apply(read_config_file(*layers.config));
    }
    for (const std::string& text : layers.overrides) values.apply({parse_override(text, names.input("override"))});
    std::vector<Assignment> given = layers.given;
    for (Assignment& a : given) a.value = checked_given(a, names);
    values.apply(given);
    refuse_grid_settings_on_all_pairs(values);
    return values;
}

BoardSetup board_setup(const SettingLayers& layers, const std::optional<std::string>& scene) {
    BoardSetup setup;
    setup.values = layered_settings(layers, scene.value_or(""), setup.board);
    const Setting& moving = *find_setting("scene.moving_fraction");
    if (scene && setup.values.settings().scene.moving_fraction != 1.0 && *scene != "spheres") {
        const std::string scene_input = setup.values.names().input("scene");
        throw InputError(setup.values.where(moving) + ": only " + scene_input + " spheres holds some of its spheres still; " +
                         (scene->empty() ? "a trace's boxes move as recorded" : scene_input + " " + *scene + " is Bullet's"));
    }
    if (scene) check_family_settings(setup.values, *scene);
    setup.platform = platform_config(setup.values);
    return setup;
}

BoardSetup checked_board_setup(const SettingLayers& layers, const std::optional<std::string>& scene) {
    BoardSetup setup = board_setup(layers, scene);
    const SettingValues& values = setup.values;
    setup.level = model_level(values, false);
    const Setting& quantum = *find_setting("run.quantum_ns");
    if ((setup.level == ModelLevel::kAnalytic || setup.level == ModelLevel::kAuto) && values.settings().run.quantum_ns != 0) {
        const Setting& fidelity = *find_setting("run.fidelity");
        throw InputError(values.where(quantum) + ": the " + name_of(setup.level) + " level (" + values.where(fidelity) +
                         ") times a host that synchronises at every access; expected 0 (docs/analytic.md)");
    }
    setup.host = resolve_host_timing(values);
    // A CPU the run could never pin to is refused here, in the caller's words
    // (a run in a child would otherwise refuse it in the command line's).
    if (const std::optional<uint32_t> cpu = values.settings().run.pinned_cpu()) {
        if (const std::optional<std::string> refused = unpinnable_cpu(*cpu)) {
            throw InputError(values.where(*find_setting("run.pin_cpu")) + ": " + *refused);
        }
    }
    if (!scene) setup.clock_warning = check_clock(values, values.settings().scene.objects);
    return setup;
}

ModelLevel model_level(const SettingValues& values, bool waves) {
    const Setting& setting = *find_setting("run.fidelity");
    const SettingNames& names = values.names();
    const ModelLevel level = values.settings().run.fidelity;
    const Setting& max_error = *find_setting("run.max_error_percent");
    if (!values.is_default(max_error) && level != ModelLevel::kAuto) {
        throw InputError(values.where(max_error) + ": only " + names.setting_to(setting, "auto") +
                         " picks a level by its error; give " + names.setting_to(setting, "auto"));
    }
    if (const Setting& lockstep = *find_setting("run.lockstep"); values.settings().run.lockstep && level != ModelLevel::kRtl) {
        throw InputError(values.where(lockstep) + ": compares the RTL with the clocked engine edge by edge, but the run is on " +
                         values.value_and_origin(setting) + ": give " + names.setting_to(setting, "rtl"));
    }
    if (waves) {
        if (!values.is_default(setting) && level != ModelLevel::kCycle && level != ModelLevel::kRtl) {
            throw InputError(names.input("vcd") + ": waveforms need the clocked engine or the RTL; " + values.where(setting) +
                             " asks for " + name_of(level) + ": use " + names.setting_to(setting, "cycle") +
                             " or rtl (or leave the fidelity out)");
        }
        return level == ModelLevel::kRtl ? ModelLevel::kRtl : ModelLevel::kCycle;
    }
    return level;
}

void add_setting_inputs(OutputSet& files, const SettingLayers& layers) {
    if (layers.board && !layers.board->empty()) {
        files.add_input(layers.names->input("board"), board_preset_path(*layers.board));
    }
    if (layers.config && !layers.config->empty()) files.add_input(layers.names->input("config"), *layers.config);
}

RunDescription describe_run(BoardSetup& setup, uint32_t capacity, const RunBudgets& budgets) {
    const Settings& settings = setup.values.settings();
    RunDescription run;
    run.capacity = capacity;
    const MemoryPlan memory = plan_memory(settings, capacity);
    memory.apply(setup.platform.board);
    run.config = setup.platform.board;
    describe_memory(run, memory.ssram);
    run.board = setup.board;
    run.host = settings.host.name;
    run.host_timing = setup.host;
    run.load_average_start = load_average();
    run.settings = &setup.values;
    run.transfer = settings.driver.transfer;
    run.wait = settings.driver.wait;
    run.quantum_ns = settings.run.quantum_ns;
    run.fidelity = setup.level;
    run.baseline_runs = settings.run.repeat;
    run.budgets = {budgets.memory_bytes(), budgets.pair_budget().max_pairs(), budgets.footprint().before_pairs(),
                   budgets.footprint().per_pair};
    run.block_rams = static_cast<uint32_t>(run.config.block_rams(run.capacity));
    return run;
}

void describe_device_fit(RunDescription& run, const Settings& settings) {
    if (has_device_family(settings)) run.device_fit = fit_on_device(settings, run.capacity);
}

void open_with_waves_and_summary(OutputSet& files, WaveOutputs& waves, const RunOutputs& outputs,
                                 const SettingNames& names, ModelLevel level) {
    if (outputs.waves) {
        waves.declare(files, outputs.waves->path, parse_dump_format(outputs.waves->format.value_or("vcd"), names),
                      names.input("vcd"), VirtualBoard::state_tables(level == ModelLevel::kRtl));
    }
    if (outputs.summary) files.add_standard_output("standard output");
    files.open();
    waves.bind(files);
}

void pin_to_setting_cpu(const SettingValues& values) {
    const std::optional<uint32_t> cpu = values.settings().run.pinned_cpu();
    if (!cpu) return;
    if (const std::optional<std::string> refused = pin_thread_to_cpu(*cpu)) {
        throw InputError(values.where(*find_setting("run.pin_cpu")) + ": " + *refused);
    }
}

}  // namespace cdvp
