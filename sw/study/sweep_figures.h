// The figures of a sweep directory, drawn by a sweep and by a merge.
#pragma once

#include <string>

#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

// Writes the data files (crossover.csv, fit.csv) and, with 'draw', the
// figures the table supports into 'dir' (one gnuplot run, all committed
// together), and prints why any figure was skipped on stderr unless 'quiet'.
// Returns the exit status: 0, or 1 when gnuplot fails. Throws SystemError or
// InputError when a file cannot be written.
int write_figures(const std::string& dir, const Grid& grid, const SweepTable& table, const std::string& program,
                  bool quiet, bool draw = true);

}  // namespace cdvp
