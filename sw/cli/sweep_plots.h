// The figures of `cdvp sweep`, as gnuplot scripts over the table's rows:
// board time and speedup against N, one line per m, per board (the paper's
// figure); the crossover N per board; the phase breakdown as stacked bars.
// Plain C++: the command runs gnuplot.
#pragma once

#include <string>
#include <vector>

#include "sw/cli/sweep_grid.h"
#include "sw/cli/sweep_table.h"

namespace cdvp {

struct Figure {
    std::string file;    // "time-adm-xrc-ii.png", "crossover.csv", ...
    std::string script;  // gnuplot commands after 'set output'; empty for a data file
    std::string data;    // the text of a data file (crossover.csv)
};

struct FigurePlan {
    std::vector<Figure> figures;
    std::vector<std::string> notes;  // plots skipped or narrowed, and why (one line each)
};

// The figures the table's ok rows support. N is the axis "objects", m the
// axis "m" (one line when it is not an axis), boards the axis "board" (else
// the report's board); every other axis with more than one value makes a
// variant that gets lines of its own ("m=8 format=fixed16"). The
// crossover is the smallest N at which the board's median frame time beats
// a baseline's (speedup >= 1), interpolated between the two measured N
// around it (linearly in log N), or the smallest N of the sweep when the
// board already wins there.
FigurePlan plan_figures(const Grid& grid, const SweepTable& table);

// The gnuplot text that draws 'figure' into 'png_path'.
std::string figure_script(const Figure& figure, const std::string& png_path);

}  // namespace cdvp
