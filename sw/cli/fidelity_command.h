// `cdvp fidelity`: the same scene at every modelling level, simulator speed
// against timing error.
#pragma once

namespace cdvp {

// Returns the process exit status (see run_command.h).
int fidelity_command(int argc, char** argv);

}  // namespace cdvp
