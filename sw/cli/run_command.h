// `cdvp run`: simulate frames on the virtual board.
#pragma once

namespace cdvp {

// Returns the process exit status: 0 done, 2 bad input, 1 simulation failure.
int run_command(int argc, char** argv);

}  // namespace cdvp
