// `cdvp merge --out OUT SHARD_DIR...`: parses its arguments and merges
// (sw/study/sweep_merge.h).
#include <iostream>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "models/common/user_text.h"
#include "sw/cli/help_text.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/run_command.h"
#include "sw/cli/run_options.h"
#include "sw/cli/sweep_command.h"
#include "sw/study/sweep_figures.h"
#include "sw/study/sweep_merge.h"
#include "sw/study/sweep_state.h"

namespace po = boost::program_options;

namespace cdvp {

namespace {

constexpr const char* kMergeHelp =
    "Usage: cdvp merge --out OUT SHARD_DIR... [-q]\n"
    "       cdvp merge OUT SHARD_DIR... [-q]\n"
    "\n"
    "Merges the directories of 'cdvp sweep --shard K/N' runs of one sweep (the same axes, options,\n"
    "input files and --record, and the same N) into OUT: sweep.csv with every shard's rows in the\n"
    "grid's order, each point's report in OUT/points (none for --record compact), and the plots.\n"
    "Every row is checked against the grid, its shard and its report first; a row that does not\n"
    "match is refused naming the file, line and field. OUT is new, empty, or a merge of the same\n"
    "sweep (its rows are kept). The merge is built beside OUT and put in place whole: a merge that\n"
    "fails leaves OUT as it was.\n"
    "Rerunning the sweep without --shard into OUT runs only the points no shard ran.\n";

std::string without_trailing_slashes(std::string path) {
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    return path;
}

std::optional<MergeSpec> parse_merge_options(int argc, char** argv) {
    for (int k = 1; k < argc && std::string(argv[k]) != "--"; ++k) {
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") return std::nullopt;
    }
    MergeSpec o;
    std::vector<std::string> dirs;
    po::options_description options;
    options.add_options()("out", po::value(&o.out), "")("quiet,q", po::bool_switch(&o.quiet), "")(
        "dirs", po::value(&dirs), "");
    po::positional_options_description positional;
    positional.add("dirs", -1);
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv)
                  .options(options)
                  .positional(positional)
                  .style(po::command_line_style::default_style & ~po::command_line_style::allow_guessing)
                  .run(),
              vm);
    po::notify(vm);
    if (vm.count("out") == 0) {
        if (dirs.empty()) throw InputError("expected --out OUT and at least one SHARD_DIR (see cdvp merge --help)");
        o.out = dirs.front();
        dirs.erase(dirs.begin());
    }
    if (o.out.empty()) throw InputError("--out: expected a directory, got ''");
    if (dirs.empty()) throw InputError("expected at least one SHARD_DIR after OUT (see cdvp merge --help)");
    o.out = without_trailing_slashes(o.out);
    for (const std::string& dir : dirs) o.shards.push_back(without_trailing_slashes(dir));
    return o;
}

int run_merge_command(MergeSpec o) {
    const MergeOutcome outcome = merge_sweeps(o);
    if (outcome.status == 0 && !o.quiet) {
        std::cout << "cdvp merge: " << outcome.points << " of " << outcome.grid << " points in " << table_path(o.out)
                  << " from " << o.shards.size() << " shards\n"
                  << answer_printout(o.out, outcome.answer);
    }
    return outcome.status;
}

}  // namespace

int merge_command(int argc, char** argv) {
    return exit_status_of("cdvp merge", [&] {
        try {
            const std::optional<MergeSpec> options = parse_merge_options(argc, argv);
            return options ? run_merge_command(*options) : print_help("cdvp merge", kMergeHelp);
        } catch (po::error& e) {
            throw InputError(option_error_text(e, "cdvp merge"));
        }
    });
}

}  // namespace cdvp
