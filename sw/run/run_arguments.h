// The one place below the command line that spells cdvp's flags: a RunSpec
// as the words of `cdvp run` (or `cdvp bullet`) for a run in a child process
// (SystemC elaborates a design once a process), and an input of a spec set
// from its text, as a sweep's axis gives it.
#pragma once

#include <string>
#include <vector>

#include "sw/run/run_spec.h"

namespace cdvp {

// The child's arguments after its command (command_of(spec)), each one word,
// so that no value is ever taken for an option: "--m=8", "-c" "bus.x=5".
std::vector<std::string> to_arguments(const RunSpec& spec);

// Sets input `key` of `spec` to `value`: a setting by its dotted name (given
// typed when `typed`, as a dedicated flag gives it, else as a NAME=VALUE
// override), or an input that is no setting: "board", "config", "trace",
// "scene", "baseline", "inject", "software-timings". Throws InputError for a
// value the setting refuses and std::invalid_argument for any other key.
void set_input(RunSpec& spec, const std::string& key, const std::string& value, bool typed);

// A comma-separated list ("sap,soa"), each item as given; an empty text is
// no item, and a comma at the end adds none.
std::vector<std::string> comma_list(const std::string& text);

}  // namespace cdvp
