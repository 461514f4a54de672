// `cdvp run`: simulate frames on the virtual board.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/fast_engine/pair_memo.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/point_options.h"
#include "sw/cli/scene_memo.h"

namespace cdvp {

// Returns the process exit status (sw/cli/exit_status.h).
int run_command(int argc, char** argv);

// What a process running many analytic runs keeps between them (a sweep's
// points): the pairs it found, the scenes it generated and the last options
// it parsed. None changes a result: a hit is the same words, the same scene
// settings, or the same options with other setting values.
struct RunMemo {
    std::shared_ptr<PairMemo> pairs = std::make_shared<PairMemo>();
    SceneMemo scenes;
    PointOptions options;
};

// `cdvp run ARGS` in this process when its settings choose the analytic
// level (which elaborates no SystemC kernel, so a process may run any number):
// the exit status, and what it printed on stderr in `errors`; none, having
// done nothing, for another level. With `report`, the report is kept there
// (its frames and summary), not written; with `memo`, pairs and scenes come
// from it when it holds them. A sweep's SweepSpec::in_process.
std::optional<int> run_analytic_in_process(const std::vector<std::string>& args, std::string& errors,
                                           nlohmann::json* report = nullptr, RunMemo* memo = nullptr);

}  // namespace cdvp
