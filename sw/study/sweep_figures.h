// The figures of a sweep directory, drawn by a sweep and by a merge.
#pragma once

#include <string>

#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

// Writes the data files (crossover.csv, fit.csv, answer.csv, answer.md)
// and, with 'draw', the figures the table supports into 'dir' (one gnuplot
// run, all committed together, so a failure leaves none of them), and prints
// why any figure was skipped on stderr unless 'quiet'. Returns the exit
// status: 0, or 1 when gnuplot fails; with 'answer', the answer's short form
// once its files are in place (sw/study/sweep_answer.h; empty without one).
// Throws SystemError or InputError when a file cannot be written.
int write_figures(const std::string& dir, const Grid& grid, const SweepTable& table, const std::string& program,
                  bool quiet, bool draw = true, std::string* answer = nullptr);

// What a sweep or merge prints of its answer: a line naming answer.md in
// 'dir', then the short form; empty when there is none.
std::string answer_printout(const std::string& dir, const std::string& short_form);

}  // namespace cdvp
