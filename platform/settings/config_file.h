// A config file (`cdvp run --config FILE`): settings by their dotted names,
// as nested sections or dotted keys, in JSON or (FILE ending in .toml) TOML:
//
//   {"board": {"m": 4}, "bus.interrupt_ns": 5000}        [board]
//                                                         m = 4
//                                                         [bus]
//                                                         interrupt_ns = 5000
//
// A value may also be a preset's {"value": ..., "source": "..."} field.
#pragma once

#include <string>
#include <vector>

#include "platform/settings/setting_values.h"

namespace cdvp {

// Every setting the file gives, checked against its setting's type and
// range. Throws InputError "FILE:LINE: NAME: ..." (TOML gives the line; JSON
// names the line only for syntax errors), an unknown name with the nearest.
std::vector<Assignment> read_config_file(const std::string& path);

// "NAME=VALUE": throws InputError "LABEL NAME: ..." for an unknown name (with
// the nearest) or a value outside its type or range; `label` is how the face
// names an override ("-c" on the command line).
Assignment parse_override(const std::string& text, const std::string& label = "override");

}  // namespace cdvp
