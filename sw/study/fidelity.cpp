#include "sw/study/fidelity.h"

#include "sw/run/run_arguments.h"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <variant>

#include "models/common/user_text.h"
#include "platform/settings/setting_choices.h"
#include "sw/scene/scene.h"
#include "sw/run/exit_codes.h"
#include "sw/study/fidelity_figure.h"
#include "sw/study/figure_plan.h"

namespace cdvp {

namespace {

constexpr const char* kTransaction = "transaction";
constexpr const char* kFormula = "formula";
constexpr std::array<FidelityLevel, kFidelityLevels> kLevels{{{ModelLevel::kCycle, kTransaction, 0},
                                                             {ModelLevel::kCycle, kFormula, 0},
                                                             {ModelLevel::kRtl, kTransaction, 0},
                                                             {ModelLevel::kRtl, kFormula, 0},
                                                             {ModelLevel::kFast, kTransaction, 0},
                                                             {ModelLevel::kFast, kFormula, 0},
                                                             {ModelLevel::kFast, kTransaction, 100},
                                                             {ModelLevel::kFast, kFormula, 100},
                                                             {ModelLevel::kFast, kTransaction, 1000},
                                                             {ModelLevel::kFast, kFormula, 1000},
                                                             {ModelLevel::kFast, kTransaction, 10000},
                                                             {ModelLevel::kFast, kFormula, 10000},
                                                             {ModelLevel::kFast, kTransaction, 100000},
                                                             {ModelLevel::kFast, kFormula, 100000},
                                                             {ModelLevel::kAnalytic, kTransaction, 0},
                                                             {ModelLevel::kAnalytic, kFormula, 0}}};

const std::array<const char*, ReportSummary::kPhases>& kPhases = ReportSummary::kPhaseKeys;
constexpr std::size_t kEnergyColumns = 6;  // the board's energy a frame, its four parts, a pair's

FidelityResult read_level(const std::string& report_path, const std::string& pairs_path) {
    const nlohmann::json report = nlohmann::json::parse(slurp(report_path));
    const ReportSummary summary = summary_from_json(report.at("summary"), "the level's report");
    FidelityResult result;
    result.mean_sim_wall_native_ns = summary.sim_wall_native_ns.mean;
    result.mean_phase_ns = summary.mean_phase_ns;
    result.mean_energy = summary.mean_energy;
    result.mean_energy_per_pair_j = summary.mean_energy_per_pair_j;
    result.frames_in_means = summary.frames_in_means;
    result.pairs = slurp(pairs_path);
    result.config = report.value("config", nlohmann::json::object());
    return result;
}

// Runs `cdvp run` at one level; its report and pairs, or the exit status
// to end with (its own one-line error already printed, under this name).
std::variant<FidelityResult, int> run_level(const FidelityLevel& level, RunSpec spec, const TraceSpool* spool) {
    ScratchFile report(".json"), pairs(".csv");
    CapturedOutput errors("cdvp-level-stderr");
    std::ostringstream quantum;
    quantum << level.quantum_ns;
    set_input(spec, "run.fidelity", level.fidelity(), true);
    set_input(spec, "bus.model", level.bus_model, true);
    set_input(spec, "run.quantum_ns", quantum.str(), true);
    spec.outputs.report = report.path();
    spec.outputs.pairs_csv = pairs.path();
    spec.outputs.summary = false;
    std::vector<std::string> args{self_path(), command_of(spec)};
    for (std::string& word : to_arguments(spec)) args.push_back(std::move(word));
    ChildStreams streams;
    streams.err = errors.fd();
    if (spool != nullptr && spool->descriptor() >= 0) streams.inherited = {spool->descriptor()};
    const int wait_status = run_child(args, streams);
    if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
    if (WEXITSTATUS(wait_status) == kExitBadInput && level.level == ModelLevel::kRtl) {
        // The scene and flags ran at the reference level before: what the
        // rtl level refuses is the board (the RTL cannot run it) or its
        // model (verilator missing, a failed compile).
        FidelityResult skipped;
        skipped.not_run = renamed_message(errors.text(64 * 1024), "cdvp fidelity");
        while (!skipped.not_run.empty() && skipped.not_run.back() == '\n') skipped.not_run.pop_back();
        return skipped;
    }
    if (WEXITSTATUS(wait_status) != 0) {
        const std::string message = renamed_message(errors.text(64 * 1024), "cdvp fidelity");
        std::cerr << (spool != nullptr ? spool->restore_names(message) : message);
        return WEXITSTATUS(wait_status);
    }
    FidelityResult result = read_level(report.path(), pairs.path());
    if (result.frames_in_means == 0) {
        throw InputError("the scene has no frames to time (--frames 0, or an empty trace); fidelity compares "
                         "frames: give at least one");
    }
    return result;
}

// "fast, quantum 100 ns", "cycle, quantum 0".
std::string level_words(const FidelityLevel& level) {
    const double q = level.quantum_ns;
    std::ostringstream words;
    words << level.fidelity() << ", " << level.bus_model << " bus, quantum ";
    if (q == 0) {
        words << 0;
    } else if (q >= 1000) {
        words << q / 1000 << " us";
    } else {
        words << q << " ns";
    }
    return words.str();
}

// The figure's context from the reference level's report: board and bus,
// scene, m, frames, and whether every level found the reference's pairs.
std::string figure_context(const std::vector<FidelityResult>& results) {
    const nlohmann::json& config = results.front().config;
    std::ostringstream words;
    words << config.value("board", std::string("no board")) << " (" << config.value("bus", std::string("untimed bus"))
          << "), " << config.value("source", std::string()) << ", m=" << config.value("m", 0) << ", "
          << results.front().frames_in_means << " frames timed\nreference: the cycle engine on the transaction-level bus at quantum 0; pairs ";
    const bool identical = std::all_of(results.begin(), results.end(), [&](const FidelityResult& r) {
        return !r.not_run.empty() || r.pairs == results.front().pairs;
    });
    words << (identical ? "identical at every level" : "DIFFER at some level (fidelity.csv)");
    return words.str();
}

}  // namespace

const char* FidelityLevel::fidelity() const { return name_of(level); }

const std::array<FidelityLevel, kFidelityLevels>& fidelity_levels() { return kLevels; }

std::optional<int> run_fidelity(const RunSpec& scene, const std::vector<std::string>& formula_overrides,
                                const TraceSpool* spool,
                                std::vector<FidelityResult>& results, const FidelityProgress& progress) {
    for (std::size_t k = 0; k < kLevels.size(); ++k) {
        if (progress) progress(k, kLevels[k], false);
        RunSpec spec = scene;
        if (kLevels[k].bus_model == kFormula) {
            spec.settings.overrides.insert(spec.settings.overrides.end(), formula_overrides.begin(), formula_overrides.end());
        }
        std::variant<FidelityResult, int> level = run_level(kLevels[k], spec, spool);
        if (progress) progress(k, kLevels[k], true);
        if (const int* status = std::get_if<int>(&level)) return *status;
        results.push_back(std::move(std::get<FidelityResult>(level)));
    }
    return std::nullopt;
}

double fidelity_error_percent(const FidelityResult& level, const FidelityResult& reference, std::size_t phase) {
    const double total = reference.mean_phase_ns.back();
    if (total == 0) return 0;
    return 100.0 * std::fabs(level.mean_phase_ns[phase] - reference.mean_phase_ns[phase]) / total;
}

std::string fidelity_csv(const std::vector<FidelityResult>& results) {
    std::ostringstream csv;
    csv << "level,fidelity,bus_model,quantum_ns,frames_in_means,mean_sim_wall_native_ns";
    for (const char* phase : kPhases) csv << ",mean_" << phase;
    for (const char* phase : kPhases) csv << ",error_" << std::string(phase, std::strlen(phase) - 3) << "_percent";
    csv << ",mean_energy_j,mean_energy_static_j,mean_energy_dynamic_j,mean_energy_bus_j,mean_energy_host_j,"
           "mean_energy_per_pair_j,pairs_identical\n";
    csv << std::setprecision(10);
    for (std::size_t k = 0; k < results.size(); ++k) {
        const FidelityResult& r = results[k];
        csv << k << ',' << kLevels[k].fidelity() << ',' << kLevels[k].bus_model << ',' << kLevels[k].quantum_ns << ',';
        if (!r.not_run.empty()) {  // empty figures, and why in the last column
            csv << std::string(2 + 2 * kPhases.size() + kEnergyColumns, ',') << "not run\n";
            continue;
        }
        csv << r.frames_in_means << ','
            << r.mean_sim_wall_native_ns;
        for (double ns : r.mean_phase_ns) csv << ',' << ns;
        for (std::size_t p = 0; p < kPhases.size(); ++p) csv << ',' << fidelity_error_percent(r, results[0], p);
        const FrameEnergy& e = r.mean_energy;
        for (double j : {e.total_j(), e.static_j, e.dynamic_j, e.bus_j, e.host_j, r.mean_energy_per_pair_j}) csv << ',' << j;
        csv << ',' << (r.pairs == results[0].pairs ? "yes" : "no") << '\n';
    }
    return csv.str();
}

std::string fidelity_table(const std::vector<FidelityResult>& results) {
    std::ostringstream t;
    t << "level                         wall/frame   total (sim)     error   energy/frame   pairs\n"
      << "                              (mean)       (mean)                    (mean)\n";
    for (std::size_t k = 0; k < results.size(); ++k) {
        const FidelityResult& r = results[k];
        std::ostringstream name;
        name << kLevels[k].fidelity() << ' ' << kLevels[k].bus_model << " q=" << kLevels[k].quantum_ns << "ns";
        if (!r.not_run.empty()) {
            t << std::left << std::setw(30) << name.str() << "not run: " << r.not_run << '\n';
            continue;
        }
        t << std::left << std::setw(30) << name.str() << std::right << std::fixed << std::setprecision(3)
          << std::setw(9) << r.mean_sim_wall_native_ns / 1e6 << " ms" << std::setw(11) << r.mean_phase_ns.back() / 1e3
          << " us" << std::setw(9) << std::setprecision(4)
          << fidelity_error_percent(r, results[0], kPhases.size() - 1) << " %" << std::setw(10)
          << std::setprecision(4) << r.mean_energy.total_j() * 1e3 << " mJ   "
          << (r.pairs == results[0].pairs ? "identical" : "DIFFER") << '\n';
    }
    return t.str();
}

std::string fidelity_plot_script(const std::vector<FidelityResult>& results, const std::string& png_path) {
    std::vector<FidelityPoint> points;
    for (std::size_t k = 0; k < results.size(); ++k) {
        if (!results[k].not_run.empty()) continue;
        points.push_back({level_words(kLevels[k]), results[k].mean_sim_wall_native_ns / 1e6,
                          fidelity_error_percent(results[k], results[0], kPhases.size() - 1)});
    }
    return figure_script(fidelity_figure(points, figure_context(results)), png_path);
}

}  // namespace cdvp
