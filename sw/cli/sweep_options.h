// The command line of `cdvp sweep`: its own options and the options of
// `cdvp run` it passes on to every point, parsed by one parser, so that a
// value is never taken for an option and every option is checked before any
// point runs. Axes are named by what they set: a flag and its setting are
// one axis, and values that mean the same are one value.
#pragma once

#include <optional>
#include <string>

#include "sw/study/sweep.h"

namespace cdvp {

// Parses argv (argv[0] is the command's name); nothing for --help. Throws
// InputError (or a program_options error) on bad input: an unknown option or
// setting, an option sweep sets itself (--report, ...), an axis given twice
// or also given as a plain option, a bad list or value, --jobs or --shard.
std::optional<SweepSpec> parse_sweep_options(int argc, char** argv);
std::string sweep_help();

}  // namespace cdvp
