// `cdvp run`: simulate frames on the virtual board.
#pragma once

#include "sw/cli/exit_status.h"

namespace cdvp {

// Returns the process exit status (sw/cli/exit_status.h).
int run_command(int argc, char** argv);

}  // namespace cdvp
