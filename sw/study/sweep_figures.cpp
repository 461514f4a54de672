#include "sw/study/sweep_figures.h"

#include <algorithm>
#include <iostream>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/sweep_plots.h"
#include "sw/output/output_set.h"

namespace cdvp {

int write_figures(const std::string& dir, const Grid& grid, const SweepTable& table, const std::string& program,
                  bool quiet, bool draw, std::string* answer) {
    FigurePlan plan = plan_figures(grid, table);
    if (!quiet && draw) {
        for (const std::string& note : plan.notes) std::cerr << program << ": " << printable(note) << '\n';
    }
    // The data files (crossover.csv, fit.csv) are written without the pictures too.
    if (!draw) {
        plan.figures.erase(std::remove_if(plan.figures.begin(), plan.figures.end(),
                                          [](const Figure& figure) { return !figure.template_name.empty(); }),
                           plan.figures.end());
    }
    if (plan.figures.empty()) return 0;
    OutputSet files;
    std::vector<std::size_t> slots;
    for (const Figure& figure : plan.figures) {
        slots.push_back(files.add_output("--out", dir + "/" + figure.file, "", figure.template_name.empty()));
    }
    files.open();
    std::string script;
    for (std::size_t k = 0; k < plan.figures.size(); ++k) {
        const Figure& figure = plan.figures[k];
        if (figure.template_name.empty()) {
            files.file(slots[k]).stream() << figure.data;
        } else {
            script += figure_script(figure, files.file(slots[k]).temp_path());
        }
    }
    if (const std::optional<std::string> error = script.empty() ? std::nullopt : run_gnuplot(script)) {
        std::cerr << program << ": gnuplot failed to draw the figures in " << printable(dir) << ": " << printable(*error)
                  << '\n';
        return 1;
    }
    if (const std::optional<OutputFailure> failure = files.try_commit()) failure->raise();
    if (answer != nullptr) *answer = plan.answer;
    return 0;
}

std::string answer_printout(const std::string& dir, const std::string& short_form) {
    if (short_form.empty()) return "";
    return "the answer (" + printable(dir + "/answer.md") +
           "): at each N, the fastest board configuration against the fastest software\n" + short_form;
}

}  // namespace cdvp
