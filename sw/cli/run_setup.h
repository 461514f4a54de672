// How `cdvp run` and `cdvp bullet` turn their options into what they
// simulate on: the settings in layers (defaults < --board preset < --config
// FILE < -c NAME=VALUE < dedicated flags), the board's checks, the platform,
// the engine, and the run's description for the report and the summary. Both
// commands call these, so a setting means the same in each and is refused
// with the same words.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "platform/setting_values.h"
#include "platform/virtual_board.h"
#include "sw/cli/host_factor.h"
#include "sw/cli/run_budgets.h"
#include "sw/cli/run_options.h"
#include "sw/cli/run_report.h"
#include "sw/cli/wave_outputs.h"
#include "sw/study/output/output_set.h"

namespace cdvp {

// What a command simulates on, from its layered settings.
struct BoardSetup {
    SettingValues values;         // every setting in effect and where it came from
    PlatformConfig platform;      // the board, its bus and driver, the engine
    std::string board = "ideal";  // the preset's name
    ModelLevel level = ModelLevel::kFast;  // as the run goes: --vcd picks cycle (model_level)
    HostTiming host;              // from native to modelled-host time
};

// The settings, each layer over the last. scene: the generated --scene
// (empty for a trace); one of Bullet's scenes is built around its own number
// of bodies, the default of scene.objects for it. Sets board_name to the
// preset's name when --board gives one. Throws InputError naming the layer
// and key.
SettingValues layered_settings(const SettingLayers& layers, const boost::program_options::variables_map& vm,
                               const std::string& scene, std::string& board_name);

// The layers and the platform they give (platform_config: the board checked,
// bus, driver, transfer and wait, engine, host quantum). The engine as --vcd
// needs it (engine_fidelity) and the host timing (resolve_host_timing) are
// the caller's to set, after whatever checks it makes first.
BoardSetup board_setup(const SettingLayers& layers, const boost::program_options::variables_map& vm,
                       const std::string& scene);

// run.fidelity: fast unless waveforms are asked for (--vcd), which need the
// clocked engine; an explicit other level with --vcd is refused naming where it came from.
ModelLevel model_level(const SettingValues& values, const boost::program_options::variables_map& vm);

// The files the settings are read from (--board's preset, --config's file):
// inputs that no output may name.
void add_setting_inputs(OutputSet& files, const SettingLayers& layers, const boost::program_options::variables_map& vm);

// What the report and the summary say of a run on a board of `capacity`
// boxes: the memory that serves them (whose tiles it sets on
// setup.platform.board, so call it before the platform is built), the
// board, host, engine, settings and budgets. The caller adds what only it
// knows: the source, the command line, the bus as the platform describes
// it, the software it times.
RunConfig describe_run(BoardSetup& setup, uint32_t capacity, const RunBudgets& budgets);
// The device's resources at every m, for a report or a summary that shows them.
void describe_device_fit(RunConfig& run, const Settings& settings);
// The command line as the report records it: "cdvp", then the command's argv.
std::vector<std::string> report_command_line(int argc, char** argv);
// run.pin_cpu: pins this thread (the simulator and the software it times)
// to the CPU, or throws InputError naming the setting and why it cannot.
void pin_to_setting_cpu(const SettingValues& values);

// What a simulating command (run, bullet) declares after its own outputs:
// the waveforms (--vcd, --vcd-format) and, unless quiet, the summary on
// standard output (an output too: committed with the files or not at all);
// then opens the set and binds the waveforms to it. `level` (model_level())
// decides what the waveforms hold: the RTL's signals or the platform's.
void open_with_waves_and_summary(OutputSet& files, WaveOutputs& waves, const boost::program_options::variables_map& vm,
                                 const std::string& vcd, const std::string& vcd_format, bool quiet, ModelLevel level);

}  // namespace cdvp
