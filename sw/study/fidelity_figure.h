// The figure of `cdvp fidelity`: the simulator's wall time per frame against
// the timing error of each modelling level, planned apart from the command
// so what it shows is tested without running gnuplot.
#pragma once

#include <string>
#include <vector>

#include "sw/study/figure_plan.h"

namespace cdvp {

struct FidelityPoint {
    std::string level;             // "fast, quantum 100 ns"
    double wall_ms_per_frame = 0;  // the simulator's, native
    double error_percent = 0;      // of the mean simulated frame time, >= 0
};

// One series per level. Both axes are logarithmic; exact levels sit on the
// error axis's floor, ticked 0; every label is placed so that
// levels with the same error and nearly the same cost do not hide one
// another. 'context' is the title's second line (board, scene, m, frames).
Figure fidelity_figure(const std::vector<FidelityPoint>& levels, const std::string& context);

}  // namespace cdvp
