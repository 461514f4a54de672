// `cdvp run`: simulate frames on the virtual board.
#pragma once

#include <string>

namespace cdvp {

// Returns the process exit status: 0 done, 2 bad input, 1 simulation failure.
int run_command(int argc, char** argv);

// 'text' safe to print on one line: control characters (a newline in a
// file name, say) become escapes such as \n and \x1b.
std::string printable(const std::string& text);

}  // namespace cdvp
