// `cdvp run`: simulate frames on the virtual board.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/cli/exit_status.h"

namespace cdvp {

// Returns the process exit status (sw/cli/exit_status.h).
int run_command(int argc, char** argv);

// `cdvp run ARGS` in this process when its settings choose the analytic
// level (which elaborates no SystemC kernel, so a process may run any number):
// the exit status, and what it printed on stderr in `errors`; none, having
// done nothing, for another level. With `report`, the report is kept there
// (its frames and summary), not written. A sweep's SweepSpec::in_process.
std::optional<int> run_analytic_in_process(const std::vector<std::string>& args, std::string& errors,
                                           nlohmann::json* report = nullptr);

}  // namespace cdvp
