#include "sw/cli/fidelity_command.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "platform/setting_choices.h"
#include "sw/study/child_runs.h"
#include "sw/study/fidelity_figure.h"
#include "sw/cli/forwarded_options.h"
#include "sw/cli/run_budgets.h"
#include "sw/study/report_summary.h"
#include "sw/cli/run_command.h"
#include "sw/study/output/output_set.h"
#include "models/common/user_text.h"
#include "sw/scene/scene.h"

namespace cdvp {

namespace {

constexpr const char* kHelp =
    "Usage: cdvp fidelity (--trace FILE | --scene spheres [--objects N] [--frames F] [--seed S])\n"
    "                     [board and host options of cdvp run] --out DIR [-q]\n"
    "\n"
    "Runs the scene at every modelling level: the clocked engine, and the fast engine with the host\n"
    "CPU's quantum at 0, 100 ns, 1 us, 10 us and 100 us. Writes DIR/fidelity.csv (per level: the\n"
    "simulator's wall time per frame, the median over the frames after --warmup; the mean simulated\n"
    "time of each phase over those frames, its error against the clocked engine at quantum 0 in\n"
    "percent of that engine's mean frame time; and whether the pairs are identical) and\n"
    "DIR/fidelity.png (wall time per frame against timing error, drawn by gnuplot).\n"
    "\n"
    "Every option of 'cdvp run' that sets the scene, board, bus or host is accepted and passed on,\n"
    "--config FILE and -c NAME=VALUE included; --fidelity, --quantum-ns (and -c run.fidelity,\n"
    "-c run.quantum_ns), --report, --pairs-out, --vcd, --inject and --baseline are set per level\n"
    "or do not apply. -q prints nothing but errors; without it the table is printed and, on a terminal,\n"
    "the level being run.\n";

struct Level {
    Fidelity engine;
    double quantum_ns;
    const char* fidelity() const { return name_of(engine); }
};
constexpr std::array<Level, 6> kLevels{{{Fidelity::kCycle, 0},
                                        {Fidelity::kFast, 0},
                                        {Fidelity::kFast, 100},
                                        {Fidelity::kFast, 1000},
                                        {Fidelity::kFast, 10000},
                                        {Fidelity::kFast, 100000}}};

constexpr const std::array<const char*, ReportSummary::kPhases>& kPhases = ReportSummary::kPhaseKeys;

// One level's figures, as its run's report summarises them: the simulator's
// wall time per frame is the median over the frames after warm-up (wall
// clock is noisy; a median is what a repeat reproduces), the simulated
// phases their means (what a user pays per frame), the same frames in both.
struct LevelResult {
    double p50_sim_wall_native_ns = 0;
    std::array<double, kPhases.size()> mean_phase_ns{};
    std::string pairs;  // the pairs CSV, to compare with the reference's
    uint64_t frames_in_means = 0;
    nlohmann::json config;  // the report's, for the figure's title
};

LevelResult read_level(const std::string& report_path, const std::string& pairs_path) {
    const nlohmann::json report = nlohmann::json::parse(slurp(report_path));
    const ReportSummary summary = summary_from_json(report.at("summary"), "the level's report");
    LevelResult result;
    result.p50_sim_wall_native_ns = summary.sim_wall_native_ns.p50;
    result.mean_phase_ns = summary.mean_phase_ns;
    result.frames_in_means = summary.frames_in_means;
    result.pairs = slurp(pairs_path);
    result.config = report.value("config", nlohmann::json::object());
    return result;
}

// Error of a phase against the reference, in percent of the reference's
// frame time (a phase may be zero, so not of its own value).
double error_percent(const LevelResult& level, const LevelResult& reference, std::size_t phase) {
    const double total = reference.mean_phase_ns.back();
    if (total == 0) return 0;
    return 100.0 * std::fabs(level.mean_phase_ns[phase] - reference.mean_phase_ns[phase]) / total;
}

std::string csv_text(const std::vector<LevelResult>& results) {
    std::ostringstream csv;
    csv << "level,fidelity,quantum_ns,frames_in_means,p50_sim_wall_native_ns";
    for (const char* phase : kPhases) csv << ",mean_" << phase;
    for (const char* phase : kPhases) csv << ",error_" << std::string(phase, std::strlen(phase) - 3) << "_percent";
    csv << ",pairs_identical\n";
    csv << std::setprecision(10);
    for (std::size_t k = 0; k < results.size(); ++k) {
        const LevelResult& r = results[k];
        csv << k << ',' << kLevels[k].fidelity() << ',' << kLevels[k].quantum_ns << ',' << r.frames_in_means << ','
            << r.p50_sim_wall_native_ns;
        for (double ns : r.mean_phase_ns) csv << ',' << ns;
        for (std::size_t p = 0; p < kPhases.size(); ++p) csv << ',' << error_percent(r, results[0], p);
        csv << ',' << (r.pairs == results[0].pairs ? "yes" : "no") << '\n';
    }
    return csv.str();
}

std::string table_text(const std::vector<LevelResult>& results) {
    std::ostringstream t;
    t << "level           wall/frame   total (sim)     error   pairs\n"
      << "                (p50)        (mean)\n";
    for (std::size_t k = 0; k < results.size(); ++k) {
        const LevelResult& r = results[k];
        std::ostringstream name;
        name << kLevels[k].fidelity() << " q=" << kLevels[k].quantum_ns << "ns";
        t << std::left << std::setw(16) << name.str() << std::right << std::fixed << std::setprecision(3)
          << std::setw(9) << r.p50_sim_wall_native_ns / 1e6 << " ms" << std::setw(11) << r.mean_phase_ns.back() / 1e3
          << " us" << std::setw(9) << std::setprecision(4) << error_percent(r, results[0], kPhases.size() - 1)
          << " %   " << (r.pairs == results[0].pairs ? "identical" : "DIFFER") << '\n';
    }
    return t.str();
}

// "fast, quantum 100 ns", "cycle, quantum 0".
std::string level_words(const Level& level) {
    const double q = level.quantum_ns;
    std::ostringstream words;
    words << level.fidelity() << ", quantum ";
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
std::string figure_context(const std::vector<LevelResult>& results) {
    const nlohmann::json& config = results.front().config;
    std::ostringstream words;
    words << config.value("board", std::string("no board")) << " (" << config.value("bus", std::string("untimed bus"))
          << "), " << config.value("source", std::string()) << ", m=" << config.value("m", 0) << ", "
          << results.front().frames_in_means << " frames timed\nreference: the cycle engine at quantum 0; pairs ";
    const bool identical = std::all_of(results.begin(), results.end(),
                                       [&](const LevelResult& r) { return r.pairs == results.front().pairs; });
    words << (identical ? "identical at every level" : "DIFFER at some level (fidelity.csv)");
    return words.str();
}

std::string plot_script(const std::vector<LevelResult>& results, const std::string& png_path) {
    std::vector<FidelityPoint> points;
    for (std::size_t k = 0; k < results.size(); ++k) {
        points.push_back({level_words(kLevels[k]), results[k].p50_sim_wall_native_ns / 1e6,
                          error_percent(results[k], results[0], kPhases.size() - 1)});
    }
    return figure_script(fidelity_figure(points, figure_context(results)), png_path);
}

// What fidelity sets for each level itself, or what does not apply to it.
bool reserved(const std::string& key) {
    for (const char* option : {"run.fidelity", "run.quantum_ns", "report", "pairs-out", "vcd", "vcd-frames", "vcd-format",
                               "inject", "baseline"}) {
        if (key == option) return true;
    }
    return false;
}

struct FidelityOptions {
    std::vector<std::string> forwarded;  // the options of cdvp run every level takes
    std::string out_dir;
    bool quiet = false;
};

FidelityOptions parse_fidelity_options(int argc, char** argv) {
    namespace po = boost::program_options;
    po::options_description own;
    own.add_options()("out", po::value<std::string>(), "")("quiet,q", po::bool_switch(), "");
    const ParsedCommandLine line = parse_with_run_options(argc, argv, own, "cdvp fidelity");
    FidelityOptions o;
    for (const ForwardedOption& option : line.forwarded) {
        if (reserved(option.key)) {
            throw InputError((option.typed.rfind("-c", 0) == 0 ? "-c " + option.key : excerpt(option.typed)) +
                             ": set by cdvp fidelity for each level, or not for it; leave it out");
        }
        o.forwarded.insert(o.forwarded.end(), option.words.begin(), option.words.end());
    }
    o.out_dir = line.values.count("out") ? line.values["out"].as<std::string>() : std::string();
    o.quiet = line.values["quiet"].as<bool>();
    if (o.out_dir.empty()) throw InputError("--out DIR is required (see cdvp fidelity --help)");
    struct stat status {};
    if (stat(o.out_dir.c_str(), &status) == 0 && !S_ISDIR(status.st_mode)) {
        throw InputError("--out: " + excerpt(o.out_dir) + ": expected a directory");
    }
    return o;
}

// Runs `cdvp run` at one level; its report and pairs, or the exit status
// to end with (its own one-line error already printed, under this name).
std::variant<LevelResult, int> run_level(const Level& level, const std::vector<std::string>& forwarded,
                                         const std::optional<TraceSpool>& spool) {
    ScratchFile report(".json"), pairs(".csv");
    CapturedOutput errors("cdvp-level-stderr");
    std::vector<std::string> args{self_path(), "run"};
    args.insert(args.end(), forwarded.begin(), forwarded.end());
    std::ostringstream quantum;
    quantum << level.quantum_ns;
    args.insert(args.end(), {"--fidelity", level.fidelity(), "--quantum-ns", quantum.str(), "--report", report.path(),
                             "--pairs-out", pairs.path(), "-q"});
    ChildStreams streams;
    streams.err = errors.fd();
    if (spool && spool->descriptor() >= 0) streams.inherited = {spool->descriptor()};
    const int wait_status = run_child(args, streams);
    if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
    if (WEXITSTATUS(wait_status) != 0) {
        const std::string message = renamed_message(errors.text(64 * 1024), "cdvp fidelity");
        std::cerr << (spool ? spool->restore_names(message) : message);
        return WEXITSTATUS(wait_status);
    }
    LevelResult result = read_level(report.path(), pairs.path());
    if (result.frames_in_means == 0) {
        throw InputError("the scene has no frames to time (--frames 0, or an empty trace); fidelity compares "
                         "frames: give at least one");
    }
    return result;
}

// fidelity.csv and fidelity.png together, and the table on stdout, or none.
int write_outputs(const FidelityOptions& o, const std::vector<LevelResult>& results, OutputSet& files,
                  CreatedDirectories& made) {
    made.create(o.out_dir);
    const std::size_t csv = files.add_output("--out", o.out_dir + "/fidelity.csv");
    const std::size_t png = files.add_output("--out", o.out_dir + "/fidelity.png", "", false);
    if (!o.quiet) files.add_standard_output("standard output");
    files.open();
    files.file(csv).stream() << csv_text(results) << std::flush;
    if (const std::optional<std::string> error = run_gnuplot(plot_script(results, files.file(png).temp_path()))) {
        std::cerr << "cdvp fidelity: gnuplot failed to draw " << o.out_dir << "/fidelity.png: " << printable(*error)
                  << '\n';
        return kExitInternal;
    }
    if (!o.quiet) files.set_standard_output(table_text(results));
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp fidelity", *failure);
    made.keep();
    return kExitDone;
}

int fidelity_levels(int argc, char** argv) {
    for (int k = 1; k < argc && std::string(argv[k]) != "--"; ++k) {
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") return print_to_stdout("cdvp fidelity", kHelp);
    }
    FidelityOptions o = parse_fidelity_options(argc, argv);
    // Declared first, so they go last: temporaries are removed before the
    // directories this run made, and a failed run leaves neither.
    CreatedDirectories made;
    OutputSet files;
    for (const std::string input : {"--trace", "--board", "--config"}) {
        const std::string path = option_value(o.forwarded, input);
        // A board given by name is a shipped preset; only a path can be an output's target.
        if (!path.empty() && (input != "--board" || path.find('/') != std::string::npos)) {
            files.add_input(input, path);
        }
    }
    // Every level reads the trace from the start (a pipe is copied once).
    std::optional<TraceSpool> spool;
    if (const std::optional<OptionValue> at = find_option(o.forwarded, "--trace")) {
        spool.emplace(o.forwarded[at->index].substr(at->offset), spooled_trace_limits());
        o.forwarded[at->index].replace(at->offset, std::string::npos, spool->path());
    }
    const bool show_progress = !o.quiet && isatty(STDERR_FILENO);
    std::vector<LevelResult> results;
    for (std::size_t k = 0; k < kLevels.size(); ++k) {
        if (show_progress) {
            std::cerr << "\rcdvp fidelity: level " << k + 1 << " of " << kLevels.size() << " (" << kLevels[k].fidelity()
                      << ", quantum " << kLevels[k].quantum_ns << " ns)   " << std::flush;
        }
        std::variant<LevelResult, int> level = run_level(kLevels[k], o.forwarded, spool);
        if (show_progress) std::cerr << '\r' << std::string(60, ' ') << '\r';
        if (const int* status = std::get_if<int>(&level)) return *status;
        results.push_back(std::move(std::get<LevelResult>(level)));
    }
    return write_outputs(o, results, files, made);
}

}  // namespace

int fidelity_command(int argc, char** argv) {
    return exit_status_of("cdvp fidelity", [&] { return fidelity_levels(argc, argv); });
}

}  // namespace cdvp
