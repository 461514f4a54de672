// Every command's --help as a terminal shows it: lines of at most 80
// columns, none ending in spaces. Boost lays the options out; this wraps what
// runs past 80 (an option's description goes on under its own column, prose
// under its own indent) and trims what boost pads.
#pragma once

#include <string>

namespace cdvp {

inline constexpr std::size_t kHelpColumns = 80;

std::string wrapped_help(const std::string& text, std::size_t columns = kHelpColumns);

// print_to_stdout of wrapped_help(text).
int print_help(const std::string& program, const std::string& text);

}  // namespace cdvp
