// The command line of `cdvp sweep`: its own options and the options of
// `cdvp run` it passes on to every point, parsed by one parser, so that a
// value is never taken for an option and every option is checked before any
// point runs. Axes are named by what they set: a flag and its setting are
// one axis, and values that mean the same are one value.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sw/study/sweep_grid.h"

namespace cdvp {

// Each running point holds its stderr in memory; 24 at once is more than two
// cores use (several shards spread further).
constexpr unsigned kMaxJobs = 24;

// A file the points read, as the command line names it: the option ("--trace",
// "--board", "--config"), the value given, and the path it is read at.
struct NamedInput {
    std::string option, value, path;
};

struct SweepOptions {
    std::vector<Axis> axes;                // in the order given, named by what they set
    std::vector<std::string> run_options;  // passed on to every point, in order, one word each
    std::vector<NamedInput> inputs;        // every file the points read
    std::string out_dir;
    unsigned jobs = 1;
    Shard shard;
    bool quiet = false;
    bool plots = true;           // --no-plots: the CSV and data files only
    bool rerun_invalid = false;  // rows that do not match the grid are run again, not refused
};

// Parses argv (argv[0] is the command's name); nothing for --help. Throws
// InputError (or a program_options error) on bad input: an unknown option or
// setting, an option sweep sets itself (--report, ...), an axis given twice
// or also given as a plain option, a bad list or value, --jobs or --shard.
std::optional<SweepOptions> parse_sweep_options(int argc, char** argv);
std::string sweep_help();

}  // namespace cdvp
