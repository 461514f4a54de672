// Axis names checked before any point runs: a flag of `cdvp run` (from its
// --help) or, once cdvp has `cdvp settings --json`, a setting's name.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "sw/cli/sweep_grid.h"

namespace cdvp {

// The names an axis may have: every long option in 'run_help' (the text of
// `cdvp run --help`; dashes dropped) but those a sweep sets itself, and
// every setting's name and flag from `cdvp_binary settings --json`. 'settings_known' tells whether the latter
// answered (without it, dotted names are left to the points to refuse).
struct AxisNames {
    std::set<std::string> names;
    bool settings_known = false;
};
AxisNames axis_names(const std::string& run_help, const std::string& cdvp_binary);

// The long options named in a `cdvp run --help` text.
std::set<std::string> help_options(const std::string& help);
// Adds the names and flags of a `cdvp settings --json` array.
void add_settings(const std::string& json, std::set<std::string>& names);

// Refuses (InputError, one line) the first axis whose name is not known,
// with the nearest known name.
void check_axis_names(const std::vector<Axis>& axes, const AxisNames& known);

// The candidate closest to 'name' by edit distance ("" for none).
std::string nearest_name(const std::string& name, const std::set<std::string>& candidates);

}  // namespace cdvp
