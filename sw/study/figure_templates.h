// The figures' gnuplot templates, sw/study/figures/NAME.gp, compiled into the
// binary (cmake/embed_figures.cmake): a figure is drawn the same wherever
// cdvp is installed, and there is no template file to find at run time.
#pragma once

#include <string>

namespace cdvp {

// The text of figures/NAME.gp; throws std::logic_error for a name with none.
const std::string& figure_template(const std::string& name);

}  // namespace cdvp
