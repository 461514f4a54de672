// The figures of `cdvp sweep`, planned from the table's rows and drawn by the
// gnuplot templates in sw/study/figures: board time and speedup against N, one
// line per m, per board (the paper's figure); the crossover N; the largest m
// that fits; the phases of a frame. Plain C++: the command runs gnuplot.
#pragma once

#include <string>
#include <vector>

#include "sw/study/figure_plan.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

struct FigurePlan {
    std::vector<Figure> figures;     // the pictures and the data files (crossover.csv, fit.csv)
    std::vector<std::string> notes;  // plots skipped or narrowed, and why (one line each)
    std::string answer;              // the answer's short form (sw/study/sweep_answer.h), lines ending in '\n'
};

// The figures the table's ok rows support. N is the axis "objects", m the
// axis "m" (one line when it is not an axis), boards the axis "board" (else
// the report's board); every other axis with more than one value makes a
// variant that gets lines of its own ("m=8 format=fixed16"). The
// crossover is the smallest N at which the board's mean frame time beats
// a baseline's (speedup >= 1), interpolated between the two measured N
// around it (linearly in log N), or the smallest N of the sweep when the
// board already wins there.
FigurePlan plan_figures(const Grid& grid, const SweepTable& table);

}  // namespace cdvp
