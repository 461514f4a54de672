// Fidelity as a study: the scene run by `cdvp run` at every modelling level
// (the clocked engine, the board RTL under Verilator, the fast engine at five
// host quanta, the analytic level; each with the bus at its transaction
// level and as the formula),
// each level's figures read back from its report's summary, and the error of
// each against the most detailed: the clocked engine on the transaction-level
// bus at quantum 0. `cdvp fidelity` parses its arguments and
// writes what this returns (docs/cli.md: cdvp fidelity).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "platform/settings/setting_choices.h"
#include "sw/study/child_runs.h"
#include "sw/run/report_summary.h"
#include "sw/run/run_spec.h"

namespace cdvp {

struct FidelityLevel {
    ModelLevel level;
    const char* bus_model;  // as --bus-model takes it
    double quantum_ns;
    const char* fidelity() const;  // the level's name, as --fidelity takes it
};

// The levels: the clocked engine, the RTL, the fast engine at five host
// quanta and the analytic level, each on the transaction-level bus and on
// the formula; the reference (the clocked engine, transaction level, quantum
// 0) first. The reference is the clocked engine, not the RTL, because the RTL
// runs only the parameter sets built in (cdvp rtl-variants); where it runs,
// lockstep holds the two equal edge by edge and its error is 0.
constexpr std::size_t kFidelityLevels = 16;
const std::array<FidelityLevel, kFidelityLevels>& fidelity_levels();

// One level's figures, as its run's report summarises them: the simulator's
// wall time per frame and the simulated phases are means over the frames
// after warm-up (what a user pays per frame, the slow frames included), the
// same frames in both.
struct FidelityResult {
    double mean_sim_wall_native_ns = 0;
    std::array<double, ReportSummary::kPhases> mean_phase_ns{};
    FrameEnergy mean_energy;            // the board's energy a frame by part (docs/energy.md)
    double mean_energy_per_pair_j = 0;
    std::string pairs;  // the pairs CSV, to compare with the reference's
    uint64_t frames_in_means = 0;
    nlohmann::json config;  // the report's, for the figure's title
    // Not empty: the level did not run on this board, and why (the rtl level
    // on a board no built variant serves); its figures are absent.
    std::string not_run;
};

// Runs every level of `scene` (a run of it, a trace read where the spool
// put it) as a child; results in level order. Returns the exit status to
// end with when a level failed (its one-line error printed on stderr under
// the name cdvp fidelity), else none. progress(k, level, done) before and
// after each. Throws InputError when the scene has no frame to time.
using FidelityProgress = std::function<void(std::size_t, const FidelityLevel&, bool)>;
// `formula_overrides`: NAME=VALUE the formula levels take over the scene's
// (the command drops a background load there: the formula cannot time one,
// and the difference is the error the ladder measures).
std::optional<int> run_fidelity(const RunSpec& scene, const std::vector<std::string>& formula_overrides,
                                const TraceSpool* spool,
                                std::vector<FidelityResult>& results, const FidelityProgress& progress);

// Error of a phase against the reference, in percent of the reference's
// mean frame time (a phase may be zero, so not of its own value).
double fidelity_error_percent(const FidelityResult& level, const FidelityResult& reference, std::size_t phase);

// fidelity.csv, the table printed, and the figure's gnuplot script.
std::string fidelity_csv(const std::vector<FidelityResult>& results);
std::string fidelity_table(const std::vector<FidelityResult>& results);
std::string fidelity_plot_script(const std::vector<FidelityResult>& results, const std::string& png_path);

}  // namespace cdvp
