// How a run's settings become what it simulates on: the settings in layers
// (defaults < preset < config file < NAME=VALUE overrides < values given
// typed), the board's checks, the platform, the engine, and the run's
// description for the report and the summary. A run of frames and a run of
// Bullet's worlds both come through here, so a setting means the same in each
// and is refused with the same words.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "platform/settings/setting_values.h"
#include "platform/virtual_board.h"
#include "sw/output/output_set.h"
#include "sw/run/host_factor.h"
#include "sw/run/run_budgets.h"
#include "sw/run/run_report.h"
#include "sw/run/run_spec.h"
#include "sw/run/wave_outputs.h"

namespace cdvp {

// What a run simulates on, from its layered settings.
struct BoardSetup {
    SettingValues values;         // every setting in effect and where it came from
    PlatformConfig platform;      // the board, its bus and driver, the engine
    std::string board = "ideal";  // the preset's name
    ModelLevel level = ModelLevel::kFast;  // as the run goes: waveforms pick cycle (model_level)
    HostTiming host;              // from native to modelled-host time
    // The clock's warning under run.ignore_timing (check_clock): from
    // checked_board_setup's check without frames (cdvp settings), else from
    // the run's at its frames' boxes, for its summary and report.
    std::optional<std::string> clock_warning;
};

// The settings, each layer over the last. scene: the generated scene's name
// (empty for a trace); one of Bullet's scenes is built around its own number
// of bodies, the default of scene.objects for it. Sets board_name to the
// preset's name when the layers give one. Throws InputError naming the layer
// and key.
SettingValues layered_settings(const SettingLayers& layers, const std::string& scene, std::string& board_name);

// The layers and the platform they give (platform_config: the board checked,
// bus, driver, transfer and wait, engine, host quantum). The level as
// waveforms need it (model_level) and the host timing (resolve_host_timing)
// are the caller's to set, after whatever checks it makes first. scene:
// nothing when the frames are not named (cdvp settings), which leaves out
// the checks of settings against the frames.
BoardSetup board_setup(const SettingLayers& layers, const std::optional<std::string>& scene);

// Every check cdvp run makes of its settings alone, whatever its frames and
// outputs: board_setup's, the level's (model_level without waveforms: the
// lockstep and the error bound against the fidelity; the analytic level's
// quantum) and the host profile's (sets setup.host); with no scene (cdvp
// settings), the clock against the device's estimated Fmax too, at the
// scene.objects boxes a generated scene would have (a run checks it at its
// frames' boxes: check_scene_fits). cdvp run, cdvp bullet
// and cdvp settings all come through here, so that each refuses the same
// settings in the same words (run.pin_cpu is held to the CPUs this process
// may run on here, and tried when a run pins). Throws
// InputError.
BoardSetup checked_board_setup(const SettingLayers& layers, const std::optional<std::string>& scene);

// run.fidelity: fast unless waveforms are asked for, which need the clocked
// engine; an explicit other level with waveforms is refused naming where it came from.
ModelLevel model_level(const SettingValues& values, bool waves);

// The files the settings are read from (the preset, the config file):
// inputs that no output may name.
void add_setting_inputs(OutputSet& files, const SettingLayers& layers);

// What the report and the summary say of a run on a board of `capacity`
// boxes: the memory that serves them (whose tiles it sets on
// setup.platform.board, so call it before the platform is built), the
// board, host, engine, settings and budgets. The caller adds what only it
// knows: the source, the command line, the bus as the platform describes
// it, the software it times.
RunDescription describe_run(BoardSetup& setup, uint32_t capacity, const RunBudgets& budgets);
// The device's resources at every m, for a report or a summary that shows them.
void describe_device_fit(RunDescription& run, const Settings& settings);
// run.pin_cpu: pins this thread (the simulator and the software it times)
// to the CPU, or throws InputError naming the setting and why it cannot.
void pin_to_setting_cpu(const SettingValues& values);

// What a run declares after its own outputs: the waveforms and, when asked,
// the summary on standard output (an output too: committed with the files or
// not at all); then opens the set and binds the waveforms to it. `level`
// decides what the waveforms hold: the RTL's signals or the platform's.
void open_with_waves_and_summary(OutputSet& files, WaveOutputs& waves, const RunOutputs& outputs,
                                 const SettingNames& names, ModelLevel level);

}  // namespace cdvp
