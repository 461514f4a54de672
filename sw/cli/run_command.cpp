#include "sw/cli/help_text.h"
#include "sw/cli/run_command.h"

#include <cstring>
#include <iostream>
#include <sstream>

#include "models/common/user_text.h"
#include "sw/cli/command_observer.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/flag_names.h"
#include "sw/run/run.h"
#include "sw/run/run_arguments.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

std::optional<std::string> given(const po::variables_map& vm, const char* option, const std::string& value) {
    return vm.count(option) ? std::optional<std::string>(value) : std::nullopt;
}

}  // namespace

SettingLayers setting_layers_of(const SettingLayersText& layers, const po::variables_map& vm) {
    SettingLayers out;
    out.board = given(vm, "board", layers.board_name);
    out.config = given(vm, "config", layers.config);
    out.overrides = layers.overrides;
    out.given = layers.flags;
    out.names = flag_names();
    return out;
}

RunSpec run_spec_of(const RunOptions& o, const po::variables_map& vm) {
    RunSpec spec;
    spec.settings = setting_layers_of(o.layers, vm);
    if (vm.count("trace") && vm.count("scene")) throw InputError("give exactly one of --trace FILE or --scene NAME");
    if (vm.count("trace")) spec.frames = TraceFrames{o.trace};
    if (vm.count("scene")) spec.frames = SceneFrames{o.scene};
    spec.baselines = comma_list(o.baselines);
    spec.software_timings = given(vm, "software-timings", o.software_timings);
    spec.faults = o.inject;
    spec.outputs.pairs_csv = given(vm, "pairs-out", o.pairs_out);
    spec.outputs.report = given(vm, "report", o.report);
    if (vm.count("vcd")) {
        spec.outputs.waves = WaveRequest{o.vcd, given(vm, "vcd-frames", o.vcd_frames), given(vm, "vcd-format", o.vcd_format)};
    } else if (vm.count("vcd-format")) {
        throw InputError("--vcd-format: the format of --vcd; give --vcd too");
    } else if (vm.count("vcd-frames")) {
        throw InputError("--vcd-frames: traces a window of frames into --vcd; give --vcd too");
    }
    spec.outputs.summary = !o.quiet;
    return spec;
}

std::vector<std::string> report_command_line(int argc, char** argv) {
    std::vector<std::string> words{"cdvp"};
    words.insert(words.end(), argv, argv + argc);
    return words;
}

int run_command(int argc, char** argv) {
    // After "--" every argument is positional, so a "--help" there is a stray word.
    for (int k = 1; k < argc && std::strcmp(argv[k], "--") != 0; ++k) {
        if (std::strcmp(argv[k], "--help") == 0 || std::strcmp(argv[k], "-h") == 0) {
            return print_help("cdvp run", run_options_help() + '\n');
        }
    }
    return exit_status_of("cdvp run", [&] {
        RunSpec spec;
        ProgressMode progress = ProgressMode::kNone;
        try {
            RunOptions o;
            const po::variables_map vm = parse_run_options(argc, argv, o);
            spec = run_spec_of(o, vm);
            progress = o.quiet ? ProgressMode::kNone : progress_mode(o.progress, "--progress");
        } catch (po::error& e) {
            RunOptions unused;
            const po::options_description options = run_options_description(unused);
            std::cerr << "cdvp run: " << option_error_text(e, "cdvp run", &options) << '\n';
            return kExitBadInput;
        }
        spec.command_line = report_command_line(argc, argv);
        CommandObserver observer("cdvp run", progress);
        return command_status("cdvp run", run(spec, observer));
    });
}

}  // namespace cdvp
