// `cdvp calibrate`: times the reference workload on this machine and writes
// a host profile, from which runs derive their host factors.
#pragma once

namespace cdvp {

// Returns the process exit status (sw/cli/exit_status.h).
int calibrate_command(int argc, char** argv);

}  // namespace cdvp
