#include "sw/cli/help_text.h"
#include "sw/cli/fidelity_command.h"

#include <sys/stat.h>
#include <unistd.h>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/cli/flag_names.h"
#include "sw/cli/forwarded_options.h"
#include "sw/run/run_budgets.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/run_options.h"
#include "sw/run/run_setup.h"
#include "sw/cli/run_command.h"
#include "sw/scene/scene.h"
#include "sw/study/child_runs.h"
#include "sw/study/fidelity.h"
#include "sw/output/output_set.h"

namespace cdvp {

namespace {

constexpr const char* kFidelityHelp =
    "Usage: cdvp fidelity (--trace FILE | --scene spheres [--objects N] [--frames F] [--seed S])\n"
    "                     [board and host options of cdvp run] --out DIR [-q]\n"
    "\n"
    "Runs the scene at every modelling level: the clocked engine, the board RTL under Verilator (a board\n"
    "no built-in variant serves has its own compiled on first use; where the RTL cannot run the board or\n"
    "verilator is missing, its rows say 'not run' and why), the fast engine with the host CPU's quantum\n"
    "at 0, 100 ns, 1 us, 10 us and 100 us, and the analytic level\n"
    "(closed forms), each with the host bus at its transaction level and as the formula (which drops a\n"
    "background load, from any layer: the formula times an idle bus). Writes DIR/fidelity.csv (per level:\n"
    "the simulator's wall time per frame, the median over the frames after --warmup; the mean simulated\n"
    "time of each phase over those frames, its error against the reference, the clocked engine on the\n"
    "transaction-level bus at quantum 0, in percent of the reference's mean frame time; and whether the\n"
    "pairs are identical) and DIR/fidelity.png (wall time per frame against timing error, both axes log,\n"
    "drawn by gnuplot).\n"
    "\n"
    "Every option of 'cdvp run' that sets the scene, board, bus or host is accepted and passed on,\n"
    "--config FILE and -c NAME=VALUE included; --fidelity, --bus-model, --quantum-ns, --max-error,\n"
    "--lockstep (and -c run.fidelity, ...), --report, --pairs-out, --vcd, --inject and --baseline are set\n"
    "per level or do not apply. -q prints nothing but errors; without it the table is printed and, on a\n"
    "terminal, the level being run.\n";

// What fidelity sets for each level itself, or what does not apply to it.
bool reserved(const std::string& key) {
    for (const char* option : {"run.fidelity", "bus.model", "run.quantum_ns", "run.max_error_percent", "run.lockstep", "report", "pairs-out", "vcd", "vcd-frames", "vcd-format",
                               "inject", "baseline"}) {
        if (key == option) return true;
    }
    return false;
}

struct FidelityOptions {
    RunSpec scene;  // what every level runs
    std::string out_dir;
    bool quiet = false;
};

FidelityOptions parse_fidelity_options(int argc, char** argv) {
    namespace po = boost::program_options;
    po::options_description own;
    own.add_options()("out", po::value<std::string>(), "")("quiet,q", po::bool_switch(), "");
    const ParsedCommandLine line = parse_with_run_options(argc, argv, own, "cdvp fidelity");
    FidelityOptions o;
    o.scene.settings.names = flag_names();
    for (const ForwardedOption& option : line.forwarded) {
        if (reserved(option.key)) {
            throw InputError((option.typed.rfind("-c", 0) == 0 ? "-c " + option.key : excerpt(option.typed)) +
                             ": set by cdvp fidelity for each level, or not for it; leave it out");
        }
        apply_forwarded(option, o.scene);
    }
    o.out_dir = line.values.count("out") ? line.values["out"].as<std::string>() : std::string();
    o.quiet = line.values["quiet"].as<bool>();
    if (line.values.count("out") == 0) throw InputError("--out DIR is required (see cdvp fidelity --help)");
    if (o.out_dir.empty()) throw InputError("--out: expected a directory, got ''");
    struct stat status {};
    if (stat(o.out_dir.c_str(), &status) == 0 && !S_ISDIR(status.st_mode)) {
        throw InputError("--out: " + excerpt(o.out_dir) + ": expected a directory");
    }
    return o;
}

// fidelity.csv and fidelity.png together, and the table on stdout, or none.
int write_outputs(const FidelityOptions& o, const std::vector<FidelityResult>& results, OutputSet& files,
                  CreatedDirectories& made) {
    made.create(o.out_dir);
    const std::size_t csv = files.add_output("--out", o.out_dir + "/fidelity.csv");
    const std::size_t png = files.add_output("--out", o.out_dir + "/fidelity.png", "", false);
    if (!o.quiet) files.add_standard_output("standard output");
    files.open();
    files.file(csv).stream() << fidelity_csv(results) << std::flush;
    if (const std::optional<std::string> error = run_gnuplot(fidelity_plot_script(results, files.file(png).temp_path()))) {
        std::cerr << "cdvp fidelity: gnuplot failed to draw " << o.out_dir << "/fidelity.png: " << printable(*error)
                  << '\n';
        return kExitInternal;
    }
    if (!o.quiet) files.set_standard_output(fidelity_table(results));
    if (const std::optional<OutputFailure> failure = files.try_commit()) return commit_failed("cdvp fidelity", *failure);
    made.keep();
    return kExitDone;
}

// A background load, from whichever layer, is dropped at the formula levels
// (which refuse one): the formula's idle-bus times against the loaded bus
// are the error the ladder reports.
std::vector<std::string> formula_overrides(const RunSpec& scene) {
    const SceneFrames* generated = scene.frames ? std::get_if<SceneFrames>(&*scene.frames) : nullptr;
    std::string board_name;
    const SettingValues values = layered_settings(scene.settings, generated ? generated->name : "", board_name);
    if (values.settings().bus_load.bytes_per_s == 0) return {};
    return {"bus.load_bytes_per_s=0"};
}

int fidelity(int argc, char** argv) {
    for (int k = 1; k < argc && std::string(argv[k]) != "--"; ++k) {
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") return print_help("cdvp fidelity", kFidelityHelp);
    }
    FidelityOptions o = parse_fidelity_options(argc, argv);
    // Declared first, so they go last: temporaries are removed before the
    // directories this run made, and a failed run leaves neither.
    CreatedDirectories made;
    OutputSet files;
    TraceFrames* trace = o.scene.frames ? std::get_if<TraceFrames>(&*o.scene.frames) : nullptr;
    if (trace != nullptr && !trace->path.empty()) files.add_input("--trace", trace->path);
    // A board given by name is a shipped preset; only a path can be an output's target.
    if (const std::optional<std::string>& board = o.scene.settings.board; board && board->find('/') != std::string::npos) {
        files.add_input("--board", *board);
    }
    if (const std::optional<std::string>& config = o.scene.settings.config; config && !config->empty()) {
        files.add_input("--config", *config);
    }
    // Every level reads the trace from the start (a pipe is copied once).
    std::optional<TraceSpool> spool;
    if (trace != nullptr && !trace->path.empty()) {
        spool.emplace(trace->path, spooled_trace_limits());
        trace->path = spool->path();
    }
    const bool show_progress = !o.quiet && isatty(STDERR_FILENO);
    std::vector<FidelityResult> results;
    const std::optional<int> failed = run_fidelity(o.scene, formula_overrides(o.scene), spool ? &*spool : nullptr, results,
                                                   [&](std::size_t k, const FidelityLevel& level, bool done) {
        if (!show_progress) return;
        if (done) {
            std::cerr << '\r' << std::string(60, ' ') << '\r';
            return;
        }
        std::cerr << "\rcdvp fidelity: level " << k + 1 << " of " << fidelity_levels().size() << " ("
                  << level.fidelity() << ", quantum " << level.quantum_ns << " ns)   " << std::flush;
    });
    if (failed) return *failed;
    return write_outputs(o, results, files, made);
}

}  // namespace

int fidelity_command(int argc, char** argv) {
    return exit_status_of("cdvp fidelity", [&] { return fidelity(argc, argv); });
}

}  // namespace cdvp
