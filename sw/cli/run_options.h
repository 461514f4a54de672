// The options of `cdvp run` and their parsing. Settings (platform/settings/settings.h)
// come in layers: defaults < --board preset < --config FILE < -c NAME=VALUE
// < dedicated flags (--m, --objects, ...), one flag per setting that has one.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "platform/settings/setting_values.h"

namespace cdvp {

// Where a command's settings come from besides the defaults, as its options
// give them (sw/run/run_spec.h's SettingLayers, once read).
struct SettingLayersText {
    std::string board_name;              // --board NAME or PATH
    std::string config;                  // --config FILE
    std::vector<std::string> overrides;  // -c NAME=VALUE, in order
    std::vector<Assignment> flags;       // the dedicated flags given
};

struct RunOptions {
    std::string trace;
    std::string scene;
    SettingLayersText layers;
    std::string baselines;
    std::string software_timings;  // a directory of shared software timings (sw/run/shared_baselines.h)
    std::vector<std::string> inject;  // fault specs, docs/faults.md
    std::string pairs_out, report, vcd;
    std::string vcd_frames;  // A:B
    std::string vcd_format = "vcd";
    std::string progress = "auto";  // --progress: auto, lines or none (sw/cli/command_observer.h)
    bool quiet = false;
    bool help = false;
};

// Parses argv (argv[0] is the command's name). Long options must be spelt
// in full (no prefix guessing) and there are no positional arguments.
// Throws boost::program_options::error or InputError on bad input.
boost::program_options::variables_map parse_run_options(int argc, char** argv, RunOptions& options);
// The same rules for any command's options: full spellings, no positional
// arguments (a stray one is refused as InputError), notified.
boost::program_options::variables_map parse_strictly(int argc, char** argv,
                                                     const boost::program_options::options_description& options);
// A command-line error's one line, an unknown option of any length quoted
// by its first bytes only, and pointing at PROGRAM --help. An unknown option
// close to one of `options` (a typo: --frmaes) is told the one it may mean.
std::string option_error_text(boost::program_options::error& error, const std::string& program,
                              const boost::program_options::options_description* options = nullptr);

// The pieces of a command line that `cdvp run` and `cdvp bullet` share, so
// that both spell and explain them alike.
// The dedicated flags of the settings of 'sections' (budgets: only the run's
// budgets, run.max_*, or none of them) that 'applies' accepts (all when
// empty), in table order; each flag given becomes one of 'given'.
void add_setting_flags(boost::program_options::options_description& group, const std::vector<std::string>& sections,
                       std::vector<Assignment>& given, bool budgets = false,
                       const std::function<bool(const Setting&)>& applies = {});
// --board NAME.
void add_board_option(boost::program_options::options_description& group, std::string& board_name);
// The group of --config FILE and -c NAME=VALUE.
boost::program_options::options_description settings_options(SettingLayersText& layers);
// --vcd FILE, --vcd-frames A:B and --vcd-format vcd|fst.
void add_wave_options(boost::program_options::options_description& group, std::string& vcd, std::string& frames,
                      std::string& format);

// The --help text.
std::string run_options_help();
// Every option of `cdvp run`, bound to 'options' (the dedicated flags of the
// settings table among them): what other commands pass on to a run parse
// with it.
boost::program_options::options_description run_options_description(RunOptions& options);

}  // namespace cdvp
