// `cdvp sweep`: a grid of settings, boards, scenes and fidelity levels, each
// point a child `cdvp run`, into one tidy CSV with plots; resumable, parallel
// and sharded. `cdvp merge`: shard directories into one.
#pragma once

namespace cdvp {

// Return the process exit status (see run_command.h).
int sweep_command(int argc, char** argv);
int merge_command(int argc, char** argv);

}  // namespace cdvp
