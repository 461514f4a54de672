#include "sw/cli/run_setup.h"

#include "sw/timing/thread_timer.h"

#include "platform/board_preset.h"
#include "platform/config_file.h"
#include "platform/device_fit.h"
#include "platform/memory_plan.h"
#include "platform/platform_settings.h"
#include "sw/bullet/scenes.h"

namespace po = boost::program_options;

namespace cdvp {

SettingValues layered_settings(const SettingLayers& layers, const po::variables_map& vm, const std::string& scene,
                               std::string& board_name) {
    SettingValues values;
    if (is_bullet_scene(scene)) {
        // Still the default: every layer above says otherwise.
        values.apply({{find_setting("scene.objects"), uint64_t{default_objects(scene)}, {}}});
    }
    if (vm.count("board")) {
        if (layers.board_name.empty()) throw InputError("--board: expected a preset name or a .json path, got ''");
        const std::shared_ptr<const BoardPreset> preset = load_shared_board_preset(layers.board_name);
        values.apply(preset->values);
        board_name = preset->name;
    }
    if (vm.count("config")) {
        if (layers.config.empty()) throw InputError("--config: expected a file path, got ''");
        values.apply(read_config_file(layers.config));
    }
    for (const std::string& text : layers.overrides) values.apply({parse_override(text)});
    values.apply(layers.flags);
    return values;
}

BoardSetup board_setup(const SettingLayers& layers, const po::variables_map& vm, const std::string& scene) {
    BoardSetup setup;
    setup.values = layered_settings(layers, vm, scene, setup.board);
    if (const Setting& moving = *find_setting("scene.moving_fraction"); setup.values.settings().scene.moving_fraction != 1.0 && scene != "spheres") {
        throw InputError(setup.values.where(moving) + ": only --scene spheres holds some of its spheres still; " +
                         (scene.empty() ? "a trace's boxes move as recorded" : "--scene " + scene + " is Bullet's"));
    }
    setup.platform = platform_config(setup.values);
    return setup;
}

ModelLevel model_level(const SettingValues& values, const po::variables_map& vm) {
    const Setting& setting = *find_setting("run.fidelity");
    const ModelLevel level = values.settings().run.fidelity;
    const Setting& max_error = *find_setting("run.max_error_percent");
    if (!values.is_default(max_error) && level != ModelLevel::kAuto) {
        throw InputError(values.where(max_error) + ": only --fidelity auto picks a level by its error; give --fidelity auto");
    }
    if (const Setting& lockstep = *find_setting("run.lockstep"); values.settings().run.lockstep && level != ModelLevel::kRtl) {
        throw InputError(values.where(lockstep) + ": compares the RTL with the clocked engine edge by edge, but the run is on " +
                         values.value_and_origin(setting) + ": give --fidelity rtl");
    }
    if (vm.count("vcd") != 0) {
        if (!values.is_default(setting) && level != ModelLevel::kCycle && level != ModelLevel::kRtl) {
            throw InputError("--vcd: waveforms need the clocked engine or the RTL; " + values.where(setting) +
                             " asks for " + name_of(level) + ": use --fidelity cycle or rtl (or leave the fidelity out)");
        }
        return level == ModelLevel::kRtl ? ModelLevel::kRtl : ModelLevel::kCycle;
    }
    return level;
}

void add_setting_inputs(OutputSet& files, const SettingLayers& layers, const po::variables_map& vm) {
    if (vm.count("board") && !layers.board_name.empty()) files.add_input("--board", board_preset_path(layers.board_name));
    if (vm.count("config") && !layers.config.empty()) files.add_input("--config", layers.config);
}

RunConfig describe_run(BoardSetup& setup, uint32_t capacity, const RunBudgets& budgets) {
    const Settings& settings = setup.values.settings();
    RunConfig run;
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
    run.transfer = settings.run.transfer;
    run.wait = settings.run.wait;
    run.quantum_ns = settings.run.quantum_ns;
    run.fidelity = setup.level;
    run.baseline_runs = settings.run.repeat;
    run.budgets = {budgets.memory_bytes(), budgets.pair_budget().max_pairs(), budgets.footprint().before_pairs(),
                   budgets.footprint().per_pair};
    run.block_rams = static_cast<uint32_t>(run.config.block_rams(run.capacity));
    return run;
}

void describe_device_fit(RunConfig& run, const Settings& settings) {
    if (has_device_family(settings)) run.device_fit = fit_on_device(settings, run.capacity);
}

std::vector<std::string> report_command_line(int argc, char** argv) {
    std::vector<std::string> words{"cdvp"};
    words.insert(words.end(), argv, argv + argc);
    return words;
}

void open_with_waves_and_summary(OutputSet& files, WaveOutputs& waves, const boost::program_options::variables_map& vm,
                                 const std::string& vcd, const std::string& vcd_format, bool quiet) {
    if (vm.count("vcd-format") && !vm.count("vcd")) throw InputError("--vcd-format: the format of --vcd; give --vcd too");
    if (vm.count("vcd")) waves.declare(files, vcd, parse_dump_format(vcd_format));
    if (!quiet) files.add_standard_output("standard output");
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
