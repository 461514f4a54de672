// The options of `cdvp run` and their parsing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "models/board/board_config.h"
#include "sw/apps/bouncing_spheres.h"
#include "sw/timing/frame_samples.h"

namespace cdvp {

struct RunOptions {
    std::string trace;
    std::string scene;
    BouncingSpheresConfig spheres;
    uint64_t objects = 500;
    uint64_t frames = 1;
    BoardConfig board;
    std::string board_name;
    std::string transfer = "dma";
    std::string wait = "irq";
    std::string baselines;
    uint64_t warmup = kDefaultWarmupFrames;  // frames left out of the timing statistics
    uint32_t repeat = 1;                     // runs of the baselines over the frames
    std::vector<std::string> inject;  // fault specs, docs/faults.md
    double host_factor = 0;  // unset: the preset's
    std::string fidelity = "fast";  // cycle when only --vcd is given
    double quantum_ns = 0;   // host CPU quantum; 0: synchronise at every access
    std::string pairs_out, report, vcd;
    std::string vcd_frames;  // A:B
    bool quiet = false;
    bool help = false;
};

// Parses argv (argv[0] is the command's name). Long options must be spelt
// in full (no prefix guessing) and there are no positional arguments.
// Throws boost::program_options::error or InputError on bad input.
boost::program_options::variables_map parse_run_options(int argc, char** argv, RunOptions& options);
// The --help text.
std::string run_options_help();

}  // namespace cdvp
