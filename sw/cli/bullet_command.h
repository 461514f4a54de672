// `cdvp bullet`: a Bullet scene stepped on the virtual board as its broad
// phase beside the same scene on one of Bullet's own, with the modelled board
// time against Bullet's broad-phase time and the whole step's time; its
// settings, checks and report are `cdvp run`'s (sw/run/run_setup.h).
// `cdvp record`: a scene's boxes written as a trace for `cdvp run`.
#pragma once

#include <boost/program_options.hpp>

#include <cstdint>
#include <functional>
#include <string>

#include "sw/bullet/scenes.h"

namespace cdvp {

// Return the process exit status (see run_command.h).
int bullet_command(int argc, char** argv);
int record_command(int argc, char** argv);

// --scene's help: Bullet's scenes.
std::string bullet_scene_help();

// Parses argv with cdvp's rules: options spelt in full, no stray words, each
// given once; --help or -h (before any "--") prints 'usage' and the options.
// Runs 'body' with the parsed options and maps what escapes it to an exit
// status with one line on stderr: InputError and bad flags 2, BoardFrameFault
// 3, anything else 1.
int run_command_line(const char* program, int argc, char** argv, const std::string& usage,
                     const boost::program_options::options_description& options,
                     const std::function<int(const boost::program_options::variables_map&)>& body);

}  // namespace cdvp
