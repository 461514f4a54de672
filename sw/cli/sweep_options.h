// The command line of `cdvp sweep`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sw/cli/sweep_grid.h"

namespace cdvp {

// Each running point holds a temporary file for its stderr, and a process
// may hold 32 (TemporaryRegistry): 24 leave room for traces and figures.
constexpr unsigned kMaxJobs = 24;

struct SweepOptions {
    std::vector<Axis> axes;                // in the order given
    std::vector<std::string> run_options;  // passed on to every point, in order
    std::string out_dir;
    unsigned jobs = 1;
    Shard shard;
    bool quiet = false;
    bool plots = true;  // --no-plots: the CSV only
};

// Parses argv (argv[0] is the command's name); nothing for --help. Throws
// InputError on bad input: an option sweep sets itself (--report, ...), an
// axis also given as a plain option, a bad list, --jobs or --shard.
std::optional<SweepOptions> parse_sweep_options(int argc, char** argv);
std::string sweep_help();

}  // namespace cdvp
