// The command lines of commands that run `cdvp run` as children (`cdvp sweep`,
// `cdvp fidelity`): their own options and the run's, parsed by one parser
// (the run's own description beside the command's), so every passed-on option
// is checked before any child runs, and each is passed on as one word: a
// value is never read as an option, by the child or by the command.
#pragma once

#include <set>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "sw/run/run_spec.h"

namespace cdvp {

// An option of `cdvp run` passed on to every child.
struct ForwardedOption {
    std::string key;                 // what it sets: a setting's name ("board.m"), else its flag ("baseline")
    std::string typed;               // the first word as the user typed it ("--m", "-cboard.m=4")
    std::string value;               // its value ("" for a switch)
    std::vector<std::string> words;  // as the child gets it: "--m=4", or "-c" "board.m=4"
};

struct ParsedCommandLine {
    std::vector<boost::program_options::option> own;  // the command's own options, in order
    std::vector<ForwardedOption> forwarded;           // the run's, in order
    boost::program_options::variables_map values;     // every option, stored (switches read from here)
};

// Parses argv with 'own' (the command's options) and every option of `cdvp
// run` whose name is not in 'own'. Throws InputError (one line, pointing at
// PROGRAM --help) for an unknown, repeated or stray option, or a setting's
// flag or -c with a bad value.
ParsedCommandLine parse_with_run_options(int argc, char** argv, const boost::program_options::options_description& own,
                                         const std::string& program);

// The names of `cdvp run`'s long options (without dashes).
std::set<std::string> run_option_names();

// Adds a passed-on option to what every child runs: a setting's flag as a
// value given typed (a switch as "yes"), -c as an override, any other input
// as set_input sets it. Throws InputError for a value its setting refuses.
void apply_forwarded(const ForwardedOption& option, RunSpec& spec);

}  // namespace cdvp
