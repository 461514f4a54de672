// `cdvp run`: simulate frames on the virtual board.
#pragma once

#include <boost/program_options.hpp>

#include "sw/cli/run_options.h"
#include "sw/run/run_spec.h"

namespace cdvp {

// Returns the process exit status (sw/run/exit_codes.h).
int run_command(int argc, char** argv);

// cdvp run's options as the run layer takes them: the settings in layers
// named by their flags, the frames, the baselines, the faults and the
// outputs. Throws InputError for what a RunSpec cannot hold (both --trace
// and --scene; --vcd-frames or --vcd-format without --vcd).
RunSpec run_spec_of(const RunOptions& options, const boost::program_options::variables_map& vm);

// The settings' layers of a command line, named by their flags.
SettingLayers setting_layers_of(const SettingLayersText& layers, const boost::program_options::variables_map& vm);

// The command line as the report records it: "cdvp", then the command's argv.
std::vector<std::string> report_command_line(int argc, char** argv);

}  // namespace cdvp
