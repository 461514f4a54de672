// `cdvp merge OUT SHARD_DIR...`: the shards of one sweep into one directory,
// as if the sweep had run there whole (so it can be resumed there too).
#include <sys/stat.h>

#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/cli/child_runs.h"
#include "sw/cli/run_command.h"
#include "sw/cli/sweep_command.h"
#include "sw/cli/sweep_files.h"

namespace cdvp {

namespace {

constexpr const char* kHelp =
    "Usage: cdvp merge OUT SHARD_DIR... [-q]\n"
    "\n"
    "Merges the directories of 'cdvp sweep --shard K/N' runs of one sweep (the same axes and options)\n"
    "into OUT: sweep.csv with every shard's rows in the grid's order, each point's report in\n"
    "OUT/points, and the plots. OUT is new, empty, or a merge of the same sweep (its rows are kept).\n"
    "Rerunning the sweep without --shard into OUT runs only the points no shard ran.\n";

bool is_empty_directory_or_missing(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return true;
    return std::filesystem::is_directory(path, error) && std::filesystem::is_empty(path, error);
}

int merge_shards(int argc, char** argv) {
    std::vector<std::string> dirs;
    bool quiet = false;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--help" || arg == "-h") return print_to_stdout("cdvp merge", kHelp);
        if (arg == "-q" || arg == "--quiet") {
            quiet = true;
        } else if (arg.rfind("-", 0) == 0) {
            throw InputError("unknown option '" + excerpt(arg) + "' (see cdvp merge --help)");
        } else {
            dirs.push_back(arg);
            while (dirs.back().size() > 1 && dirs.back().back() == '/') dirs.back().pop_back();
        }
    }
    if (dirs.size() < 2) throw InputError("expected OUT and at least one SHARD_DIR (see cdvp merge --help)");
    const std::string out = dirs[0];
    const std::vector<std::string> shards(dirs.begin() + 1, dirs.end());

    std::vector<nlohmann::json> manifests;
    std::set<std::string> seen;
    for (const std::string& dir : shards) {
        const std::optional<nlohmann::json> m = read_manifest(dir);
        if (!m) throw InputError(excerpt(dir) + ": not a sweep directory (no sweep.json)");
        if (!manifests.empty() && !same_sweep(manifests[0], *m)) {
            throw InputError(excerpt(dir) + ": a shard of another sweep than " + excerpt(shards[0]) +
                             " (other axes or options)");
        }
        if (!seen.insert(m->at("shard").get<std::string>()).second) {
            throw InputError(excerpt(dir) + ": shard " + m->at("shard").get<std::string>() + " is given twice");
        }
        manifests.push_back(*m);
    }
    const Grid grid = manifest_grid(manifests[0]);
    nlohmann::json merged = manifest(grid, manifest_run_options(manifests[0]), Shard{});
    const std::optional<nlohmann::json> existing = read_manifest(out);
    if (existing ? !same_sweep(*existing, merged) || existing->at("shard") != merged.at("shard")
                 : !is_empty_directory_or_missing(out)) {
        throw InputError(excerpt(out) + ": expected a new or empty directory, or a merge of the same sweep");
    }

    SweepTable table(grid);
    read_table(out, table);
    CreatedDirectories made;
    made.create(out, "OUT");
    made.create(points_dir(out), "OUT");
    for (const std::string& dir : shards) {
        SweepTable shard(grid);
        read_table(dir, shard);
        for (const auto& [index, row] : shard.rows()) {
            if (row.at("status") == "ok") {
                const Point point = grid.point(index);
                const std::string from = report_path(dir, point);
                struct stat status {};
                if (stat(from.c_str(), &status) != 0) throw InputError(excerpt(from) + ": a point's report is missing");
                commit_text_file(report_path(out, point), slurp(from), "OUT");
            }
            table.add(index, PointRow{shard.columns(), row});
        }
    }
    commit_text_file(manifest_path(out), merged.dump(2) + "\n", "OUT");
    commit_text_file(table_path(out), table.csv(), "OUT");
    made.keep();
    const int status = write_figures(out, grid, table, "cdvp merge", quiet);
    if (status == 0 && !quiet) {
        std::cout << "cdvp merge: " << table.rows().size() << " of " << grid.size() << " points in " << table_path(out)
                  << " from " << shards.size() << " shards\n";
    }
    return status;
}

}  // namespace

int merge_command(int argc, char** argv) {
    return exit_status_of("cdvp merge", [&] { return merge_shards(argc, argv); });
}

}  // namespace cdvp
