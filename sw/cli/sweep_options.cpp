#include "sw/cli/sweep_options.h"

#include <algorithm>
#include <set>

#include <boost/program_options.hpp>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "platform/settings/board_preset.h"
#include "platform/settings/config_file.h"
#include "platform/settings/settings.h"
#include "sw/cli/flag_names.h"
#include "sw/cli/forwarded_options.h"
#include "sw/cli/run_options.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_inputs.h"
#include "sw/study/sweep_state.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kSweepHelp =
    "Usage: cdvp sweep [--board LIST] [--set NAME=LIST]... [--fidelity LIST] [--scene LIST | --trace LIST]\n"
    "                  [options of cdvp run] --out DIR [--jobs J] [--shard K/N] [--record full|compact]\n"
    "                  [--software-timings DIR|none] [--no-plots] [--rerun-invalid] [-q]\n"
    "\n"
    "Runs 'cdvp run' once for every point of the grid (every combination of the axes' values, the\n"
    "first axis outermost) and gathers the points into DIR/sweep.csv, one row per point, with each\n"
    "point's report in DIR/points/ID.json, plots drawn by gnuplot, and its answer in DIR/answer.md\n"
    "and answer.csv: at each N the fastest board configuration against the fastest software, and\n"
    "from which N the board wins on time and on energy (docs/sweep.md). Points at\n"
    "--fidelity analytic run inside the sweep's own process, one at a time; the others as children.\n"
    "\n"
    "Axes:\n"
    "  --board LIST, --fidelity LIST, --scene LIST, --trace LIST   comma-separated values\n"
    "  --set NAME=LIST     NAME: a flag of cdvp run without its dashes (m, objects, frames, seed,\n"
    "                      clock-mhz, quantum-ns, transfer, wait, ...) or a setting's name\n"
    "                      (bus.interrupt_ns; cdvp settings lists them); a flag and its setting\n"
    "                      are one axis. Values are checked before any point runs.\n"
    "                      LIST: a,b,c | A:B:xF (A, A*F, ... up to B) | A:B:+S (A, A+S, ... up to B)\n"
    "Every other option is passed on to every point unchanged (--frames 30 --baseline sap,soa ...);\n"
    "without --scene or --trace the points run --scene spheres.\n"
    "\n"
    "  --out DIR           the sweep's directory (made with its parents; new, empty or this sweep's).\n"
    "                      Rerunning the same command into it runs only the points not done yet, after\n"
    "                      checking every row kept; another grid, other options or a changed input\n"
    "                      file is refused. One sweep or merge at a time writes a directory.\n"
    "  --jobs J            points run in J processes at once (1 to 24; 1)\n"
    "  --shard K/N         run only the points whose index % N is K-1, for 'cdvp merge'\n"
    "  --record full|compact\n"
    "                      full: each point's report in DIR/points and every setting in its row;\n"
    "                      compact: no report, a row of the axes and the figures (pairs, cycles,\n"
    "                      phases, totals, speedups), about 300 bytes a point (full)\n"
    "  --software-timings DIR|none\n"
    "                      the software baselines are timed once a workload (the scene and its\n"
    "                      settings or the trace, the baselines, repeats and warm-up: not the board, m\n"
    "                      or bus), by its first point, kept in DIR/KEY.json and used by every point\n"
    "                      of it, so speedups across boards share one denominator; each row names\n"
    "                      its timing (NAME_timing_id). Shards given one DIR share it too. none: each\n"
    "                      point times its own (OUT/software)\n"
    "  --no-plots          write no figures (shards on a cluster, say: cdvp merge draws them)\n"
    "  --rerun-invalid     rows of sweep.csv that do not match the grid or their reports are run\n"
    "                      again instead of refused\n"
    "  -q [ --quiet ]      print nothing but errors (else: a progress bar on a terminal, a summary\n"
    "                      and the answer's short form)\n"
    "\n"
    "A point that cdvp run refuses (status 2: m does not fit the device, say) or that faults\n"
    "(status 3) is a row with its status and reason; if every point is refused, the sweep exits 2\n"
    "with the first reason. A point whose output the system could not write (status 4, a full\n"
    "disk) is no row: the sweep stops with that status, and a rerun runs the point again.\n"
    "\n"
    "'cdvp merge --out OUT SHARD_DIR...' merges the shard directories of one sweep (cdvp merge --help).\n";

// The sweep's own options; the axis options take lists.
po::options_description own_options(std::vector<std::string>& sets) {
    po::options_description own;
    own.add_options()
        ("board", po::value<std::string>(), "")("fidelity", po::value<std::string>(), "")
        ("scene", po::value<std::string>(), "")("trace", po::value<std::string>(), "")
        ("set", po::value(&sets)->composing(), "")("out", po::value<std::string>(), "")
        ("jobs", po::value<std::string>(), "")("shard", po::value<std::string>(), "")
        ("record", po::value<std::string>(), "")("software-timings", po::value<std::string>(), "")
        ("no-plots", po::bool_switch(), "")("rerun-invalid", po::bool_switch(), "")
        ("quiet,q", po::bool_switch(), "")("help,h", po::bool_switch(), "");
    return own;
}

bool is_axis_option(const std::string& key) {
    return key == "board" || key == "fidelity" || key == "scene" || key == "trace";
}

unsigned parse_jobs(const std::string& text) {
    if (text.empty() || text.size() > 2 || text.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(text) < 1 || std::stoul(text) > kMaxJobs) {
        throw InputError("--jobs: expected a whole number from 1 to " + std::to_string(kMaxJobs) + ", got '" +
                         excerpt(text) + "'");
    }
    return static_cast<unsigned>(std::stoul(text));
}

// The setting a name means: by its dotted name or by its flag.
const Setting* setting_of(const std::string& name) {
    if (const Setting* s = find_setting(name)) return s;
    for (const Setting& s : settings_table()) {
        if (!s.flag.empty() && s.flag == name) return &s;
    }
    return nullptr;
}

// Every name an axis may have, for the nearest one in a refusal.
std::vector<std::string> axis_names(const std::set<std::string>& run_flags) {
    std::vector<std::string> names(run_flags.begin(), run_flags.end());
    for (const Setting& s : settings_table()) names.push_back(s.name);
    return names;
}

// Names the axis by what it sets and checks its values: a setting's by the
// setting's own parser, so that a bad value is refused before any point runs
// and two spellings of one value are one value.
void resolve_axis(Axis& axis, const std::string& label, const std::set<std::string>& run_flags) {
    if (const Setting* s = setting_of(axis.name)) {
        axis.key = s->name;
        axis.flag = s->value_name.empty() ? std::string() : s->flag;  // a switch's value goes through -c
        std::vector<std::string> canonical;  // each value as the setting reads it
        canonical.reserve(axis.values.size());
        for (const std::string& value : axis.values) {
            try {
                canonical.push_back(to_text(s->parse_text(value)));
            } catch (const std::invalid_argument& e) {
                throw InputError(label + ": " + e.what());
            }
        }
        if (const auto repeat = first_repeat(canonical)) {
            throw InputError(label + ": '" + excerpt(axis.values[repeat->first]) + "' is the same value as '" +
                             excerpt(axis.values[repeat->second]) + "'; give each value once");
        }
        return;
    }
    if (run_flags.count(axis.name) == 0) {
        const std::optional<std::string> nearest = nearest_name(axis.name, axis_names(run_flags));
        throw InputError(label + ": no flag of cdvp run or setting has this name" +
                         (nearest ? "; the nearest is '" + *nearest + "'" : "") + " (see cdvp run --help, cdvp settings)");
    }
    axis.key = axis.flag = axis.name;
    // Refused here, naming the file and key or line, rather than by every point.
    for (const std::string& value : axis.values) {
        if (axis.key == "board") load_board_preset(value, "--board");
        if (axis.key == "config") read_config_file(value);
    }
}

// The sweep's own options: its axes (--NAME LIST and --set NAME=LIST), --out,
// --jobs, --shard and --record.
void read_own_options(const ParsedCommandLine& line, const std::set<std::string>& run_flags, SweepSpec& o) {
    bool software_timings_given = false;
    std::vector<std::string> labels;  // each axis's, for resolve_axis
    for (const po::option& option : line.own) {
        const std::string& key = option.string_key;
        if (is_axis_option(key)) {
            o.axes.push_back(Axis{key, expand_list(option.value.at(0), "--" + key, false)});
            labels.push_back("--" + key);
        } else if (key == "set") {
            o.axes.push_back(parse_set(option.value.at(0)));
            labels.push_back("--set " + o.axes.back().name);
        } else if (key == "out") {
            o.out_dir = option.value.at(0);
            if (o.out_dir.empty()) throw InputError("--out: expected a directory, got ''");
            while (o.out_dir.size() > 1 && o.out_dir.back() == '/') o.out_dir.pop_back();
        } else if (key == "jobs") {
            o.jobs = parse_jobs(option.value.at(0));
        } else if (key == "shard") {
            o.shard = parse_shard(option.value.at(0));
        } else if (key == "record") {
            o.record = parse_record_mode(option.value.at(0), "--record");
        } else if (key == "software-timings") {
            o.software_timings = option.value.at(0);
            if (o.software_timings.empty()) throw InputError("--software-timings: expected a directory or none, got ''");
            while (o.software_timings.size() > 1 && o.software_timings.back() == '/') o.software_timings.pop_back();
            if (o.software_timings == "none") o.software_timings.clear();
            software_timings_given = true;
            o.software_timings_given = !o.software_timings.empty();
        }
    }
    if (!software_timings_given && !o.out_dir.empty()) o.software_timings = software_timings_dir(o.out_dir);
    // The grid's size from the axes' lengths, before any value is read by its
    // setting or file: a grid too big to run is refused at once.
    check_grid_size(o.axes);
    for (std::size_t a = 0; a < o.axes.size(); ++a) resolve_axis(o.axes[a], labels[a], run_flags);
}

// The options of cdvp run every point takes: none the sweep sets itself,
// none that is also an axis; a config file is read here, so that it is
// refused before any point runs.
void read_forwarded_options(const ParsedCommandLine& line, SweepSpec& o) {
    for (const ForwardedOption& option : line.forwarded) {
        if (option.key == "report" || option.key == "pairs-out" || option.key == "vcd" || option.key == "vcd-frames" ||
            option.key == "vcd-format") {
            throw InputError("--" + option.key + ": set by cdvp sweep for each point, or not for it; leave it out");
        }
        for (const Axis& axis : o.axes) {
            if (axis.key == option.key) {
                throw InputError(excerpt(option.typed) + ": " + option.key + " is an axis of the sweep (" +
                                 excerpt(axis.name) + "); give it once");
            }
        }
        apply_forwarded(option, o.run);
        if (option.key == "config") {
            if (option.value.empty()) throw InputError("--config: expected a file path, got ''");
            read_config_file(option.value);  // refused here, naming file and line
            o.inputs.push_back({"--config", option.value, option.value});
        }
        if (option.key == "host.profile" && !option.value.empty()) {
            o.inputs.push_back({"--host-profile", option.value, option.value});
        }
    }
}

}  // namespace

std::string sweep_help() { return kSweepHelp; }

std::optional<SweepSpec> parse_sweep_options(int argc, char** argv) {
    for (int k = 1; k < argc && std::string(argv[k]) != "--"; ++k) {
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") return std::nullopt;
    }
    std::vector<std::string> sets;
    const ParsedCommandLine line = parse_with_run_options(argc, argv, own_options(sets), "cdvp sweep");
    std::set<std::string> run_flags = run_option_names();
    for (const char* own : {"help", "quiet", "report", "pairs-out", "vcd", "vcd-frames", "vcd-format"}) run_flags.erase(own);

    SweepSpec o;
    o.run.settings.names = flag_names();
    read_own_options(line, run_flags, o);
    read_forwarded_options(line, o);
    o.quiet = line.values["quiet"].as<bool>();
    o.plots = !line.values["no-plots"].as<bool>();
    o.rerun_invalid = line.values["rerun-invalid"].as<bool>();
    if (o.out_dir.empty()) throw InputError("--out DIR is required (see cdvp sweep --help)");
    name_sweep_inputs(o);
    return o;
}

}  // namespace cdvp
