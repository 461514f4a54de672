#include "sw/cli/sweep_options.h"

#include "models/common/user_text.h"

namespace cdvp {

namespace {

constexpr const char* kHelp =
    "Usage: cdvp sweep [--board LIST] [--set NAME=LIST]... [--fidelity LIST] [--scene LIST | --trace LIST]\n"
    "                  [options of cdvp run] --out DIR [--jobs J] [--shard K/N] [--no-plots] [-q]\n"
    "\n"
    "Runs 'cdvp run' once for every point of the grid (every combination of the axes' values, the\n"
    "first axis outermost) and gathers the points into DIR/sweep.csv, one row per point, with each\n"
    "point's report in DIR/points/ID.json and plots drawn by gnuplot (docs/sweep.md).\n"
    "\n"
    "Axes:\n"
    "  --board LIST, --fidelity LIST, --scene LIST, --trace LIST   comma-separated values\n"
    "  --set NAME=LIST     NAME: a flag of cdvp run without its dashes (m, objects, frames, seed,\n"
    "                      clock-mhz, quantum-ns, transfer, wait, ...), passed as --NAME V, or a\n"
    "                      dotted setting name (bus.interrupt_ns), passed as -c NAME=V.\n"
    "                      LIST: a,b,c | A:B:xF (A, A*F, ... up to B) | A:B:+S (A, A+S, ... up to B)\n"
    "Every other option is passed on to every point unchanged (--frames 30 --baseline sap,soa ...);\n"
    "without --scene or --trace the points run --scene spheres.\n"
    "\n"
    "  --out DIR           the sweep's directory (made with its parents). Rerunning the same command\n"
    "                      into it skips the points already in sweep.csv; another grid is refused.\n"
    "  --jobs J            points run in J processes at once (1 to 24; 1)\n"
    "  --shard K/N         run only the points whose index % N is K-1, for 'cdvp merge'\n"
    "  --no-plots          write no figures (shards on a cluster, say: cdvp merge draws them)\n"
    "  -q [ --quiet ]      print nothing but errors (else: a progress bar on a terminal, a summary)\n"
    "\n"
    "A point that cdvp run refuses (status 2: m does not fit the device, say) or that faults\n"
    "(status 3) is a row with its status and reason; if every point is refused, the sweep exits 2\n"
    "with the first reason.\n"
    "\n"
    "'cdvp merge OUT SHARD_DIR...' merges the shard directories of one sweep into OUT (cdvp merge --help).\n";

// "--NAME V" or "--NAME=V" at args[k]: the value, advancing k past it.
std::optional<std::string> value_of(const std::vector<std::string>& args, std::size_t& k, const std::string& name) {
    if (args[k] == name) {
        if (k + 1 == args.size()) throw InputError(name + ": expected a value");
        return args[++k];
    }
    if (args[k].rfind(name + "=", 0) == 0) return args[k].substr(name.size() + 1);
    return std::nullopt;
}

unsigned parse_jobs(const std::string& text) {
    if (text.empty() || text.size() > 2 || text.find_first_not_of("0123456789") != std::string::npos ||
        std::stoul(text) < 1 || std::stoul(text) > kMaxJobs) {
        throw InputError("--jobs: expected a whole number from 1 to " + std::to_string(kMaxJobs) + ", got '" +
                         excerpt(text) + "'");
    }
    return static_cast<unsigned>(std::stoul(text));
}

// An option given to every point that an axis also sets.
void refuse_axis_options(const SweepOptions& o) {
    for (std::size_t k = 0; k < o.run_options.size(); ++k) {
        const std::string& arg = o.run_options[k];
        std::string name;
        if (arg.rfind("--", 0) == 0) name = arg.substr(2, arg.find('=') - 2);
        if (arg == "-c" && k + 1 < o.run_options.size()) name = o.run_options[k + 1].substr(0, o.run_options[k + 1].find('='));
        if (arg.rfind("-c", 0) == 0 && arg.size() > 2) name = arg.substr(2, arg.find('=') - 2);  // -cNAME=V
        for (const Axis& axis : o.axes) {
            if (!name.empty() && axis.name == name) {
                throw InputError(excerpt(arg) + ": " + name + " is an axis of the sweep; give it once");
            }
        }
    }
}

}  // namespace

std::string sweep_help() { return kHelp; }

std::optional<SweepOptions> parse_sweep_options(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    SweepOptions o;
    bool out_given = false;
    for (std::size_t k = 0; k < args.size(); ++k) {
        const std::string& arg = args[k];
        if (arg == "--help" || arg == "-h") return std::nullopt;
        if (arg == "-q" || arg == "--quiet") {
            o.quiet = true;  // the points run quiet anyway
            continue;
        }
        if (arg == "--no-plots") {
            o.plots = false;
            continue;
        }
        bool axis_flag = false;
        for (const char* name : {"board", "fidelity", "scene", "trace"}) {
            if (const std::optional<std::string> list = value_of(args, k, std::string("--") + name)) {
                o.axes.push_back({name, expand_list(*list, std::string("--") + name, false)});
                axis_flag = true;
                break;
            }
        }
        if (axis_flag) continue;
        if (const std::optional<std::string> set = value_of(args, k, "--set")) {
            o.axes.push_back(parse_set(*set));
        } else if (const std::optional<std::string> out = value_of(args, k, "--out")) {
            if (out->empty()) throw InputError("--out: expected a directory, got ''");
            o.out_dir = *out;
            while (o.out_dir.size() > 1 && o.out_dir.back() == '/') o.out_dir.pop_back();
            out_given = true;
        } else if (const std::optional<std::string> jobs = value_of(args, k, "--jobs")) {
            o.jobs = parse_jobs(*jobs);
        } else if (const std::optional<std::string> shard = value_of(args, k, "--shard")) {
            o.shard = parse_shard(*shard);
        } else {
            for (const char* own : {"--report", "--pairs-out", "--vcd", "--vcd-frames"}) {
                if (arg == own || arg.rfind(std::string(own) + "=", 0) == 0) {
                    throw InputError(excerpt(arg) + ": set by cdvp sweep for each point, or not for it; leave it out");
                }
            }
            o.run_options.push_back(arg);
        }
    }
    if (!out_given) throw InputError("--out DIR is required (see cdvp sweep --help)");
    bool has_source = false;
    for (const Axis& axis : o.axes) has_source |= axis.name == "scene" || axis.name == "trace";
    if (!has_source) o.run_options.insert(o.run_options.begin(), {"--scene", "spheres"});
    refuse_axis_options(o);
    return o;
}

}  // namespace cdvp
