#include "sw/cli/sweep_command.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/directory_lock.h"
#include "sw/cli/exit_status.h"
#include "sw/cli/machine_memory.h"
#include "sw/cli/run_budgets.h"
#include "sw/cli/sweep_files.h"
#include "sw/study/sweep_manifest.h"
#include "sw/cli/sweep_options.h"
#include "sw/cli/sweep_progress.h"
#include "sw/cli/sweep_runner.h"
#include "sw/study/sweep_state.h"
#include "sw/cli/version.h"

namespace cdvp {

namespace {

namespace fs = std::filesystem;

// User and system CPU time of the process or of its waited-for children.
std::string cpu_seconds(int who) {
    struct rusage usage {};
    getrusage(who, &usage);
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; };
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds(usage.ru_utime) + seconds(usage.ru_stime));
    return text;
}

// The files the points read, each as the points see it (a pipe spooled once)
// and its digest; and a check, after each point, that none has changed since.
class SweepInputs {
public:
    explicit SweepInputs(const std::vector<NamedInput>& named) {
        for (const NamedInput& input : named) {
            std::string path = input.path;
            if (input.option == "--trace") {
                if (spools_.count(input.value) == 0) {
                    spools_.emplace(std::piecewise_construct, std::forward_as_tuple(input.value),
                                    std::forward_as_tuple(input.value, spooled_trace_limits()));
                }
                path = spools_.at(input.value).path();
                trace_paths_[input.value] = path;
            }
            struct stat before {};
            const bool regular = stat(path.c_str(), &before) == 0 && S_ISREG(before.st_mode);
            digests_.push_back(digest_input(input.option, input.value, path));
            if (regular) watched_.push_back({digests_.back(), before});
        }
    }
    const std::vector<SweepInput>& digests() const { return digests_; }
    const std::map<std::string, std::string>& trace_paths() const { return trace_paths_; }

    // Throws InputError when a file the points read was changed or replaced.
    void check_unchanged() const {
        for (const Watched& w : watched_) {
            struct stat now {};
            if (stat(w.input.path.c_str(), &now) == 0 && now.st_ino == w.status.st_ino && now.st_dev == w.status.st_dev &&
                now.st_size == w.status.st_size && now.st_mtim.tv_sec == w.status.st_mtim.tv_sec &&
                now.st_mtim.tv_nsec == w.status.st_mtim.tv_nsec) {
                continue;
            }
            throw InputError(w.input.option + " " + excerpt(w.input.value) +
                             " changed while the sweep ran; the points recorded before stay: restore it to resume");
        }
    }

private:
    struct Watched {
        SweepInput input;
        struct stat status;
    };
    std::map<std::string, TraceSpool> spools_;
    std::map<std::string, std::string> trace_paths_;
    std::vector<SweepInput> digests_;
    std::vector<Watched> watched_;
};

// Temporaries left by a killed sweep or point (*.part-*): under the lock no
// one else writes them.
void remove_stale_temporaries(const std::string& dir) {
    for (const std::string& where : {dir, points_dir(dir)}) {
        std::error_code error;
        for (const auto& entry : fs::directory_iterator(where, error)) {
            if (entry.is_regular_file() && entry.path().filename().string().find(".part-") != std::string::npos) {
                fs::remove(entry.path(), error);
            }
        }
    }
}

// Refuses an --out that holds another sweep, another shard of this one, or
// files that are no sweep's.
void check_out_dir(const std::string& out, const std::optional<Manifest>& existing, const Manifest& wanted) {
    const std::string dir = excerpt(out);
    if (existing) {
        if (const std::optional<SweepDifference> other = difference(*existing, wanted)) {
            if (other->input_changed) {
                throw InputError("--out: " + dir + ": " + other->what + ": restore it to resume, or give a new --out");
            }
            throw InputError("--out: " + dir + " holds another sweep (" + other->what +
                             "); give a new --out, or the same command to resume it");
        }
        if (existing->shard.text() != wanted.shard.text()) {
            throw InputError("--out: " + dir + " holds shard " + existing->shard.text() + " of this sweep, not " +
                             wanted.shard.text() + "; give the same --shard, or a new --out");
        }
        return;
    }
    const std::vector<std::string> names = directory_contents(out);
    if (!names.empty()) {
        throw InputError("--out: " + dir + " holds " + excerpt(names.front()) +
                         (names.size() > 1 ? " and " + std::to_string(names.size() - 1) + " more" : std::string()) +
                         " but no sweep.json: not a sweep's directory, or one whose manifest is gone; give a new or "
                         "empty --out");
    }
}

// Every row refused (a device too small for every m, say): the first reason.
bool every_point_refused(const SweepTable& table, std::string& first) {
    bool all = table.size() > 0;
    table.for_each([&](std::size_t, const RowView& row) {
        if (row.get("status") != "refused") all = false;
        if (first.empty()) first = row.get("point") + ": " + row.get("reason");
    });
    return all;
}

void print_summary(const std::string& out, const SweepTable& table, std::size_t run_now) {
    std::size_t counts[3] = {};
    table.for_each([&](std::size_t, const RowView& row) {
        const std::string status = row.get("status");
        counts[status == "ok" ? 0 : status == "refused" ? 1 : 2] += 1;
    });
    std::cout << "cdvp sweep: " << table.size() << " points in " << table_path(out) << ": " << counts[0] << " ok, "
              << counts[1] << " refused, " << counts[2] << " faulted (" << run_now << " run now; CPU time "
              << cpu_seconds(RUSAGE_SELF) << " s in the sweep, " << cpu_seconds(RUSAGE_CHILDREN)
              << " s in its points and plots)\n";
}

int run_sweep(const SweepOptions& o) {
    const Grid grid(o.axes);
    const SweepInputs inputs(o.inputs);
    const Manifest wanted{grid.axes(), o.run_options, inputs.digests(), o.shard, kCdvpVersion};
    struct stat out_status {};
    if (stat(o.out_dir.c_str(), &out_status) == 0 && !S_ISDIR(out_status.st_mode)) {
        throw InputError("--out: " + excerpt(o.out_dir) + ": expected a directory");
    }
    CreatedDirectories made;
    made.create(o.out_dir);
    DirectoryLock lock(o.out_dir, "--out");
    const std::optional<Manifest> existing = read_manifest(manifest_path(o.out_dir));
    check_out_dir(o.out_dir, existing, wanted);
    remove_stale_temporaries(o.out_dir);

    SweepTable table(grid);
    const TableRead read = read_table(o.out_dir, grid, o.shard, table, o.rerun_invalid);
    if (!o.quiet) {
        for (const std::string& invalid : read.invalid) std::cerr << "cdvp sweep: runs again: " << invalid << '\n';
        if (read.torn) std::cerr << "cdvp sweep: " << table_path(o.out_dir) << ": its last row was cut short; the point runs again\n";
    }
    std::vector<std::size_t> todo;
    std::size_t in_shard = 0;
    for (std::size_t index = 0; index < grid.size(); ++index) {
        if (!o.shard.runs(index)) continue;
        ++in_shard;
        if (!table.has(index)) todo.push_back(index);
    }
    made.create(points_dir(o.out_dir));
    if (!existing) commit_text_file(manifest_path(o.out_dir), wanted.to_json().dump(2) + "\n", "--out");
    TableFile file(table_path(o.out_dir), table, read.rewrite);
    SweepProgress progress(in_shard, in_shard - todo.size(), !o.quiet && isatty(STDERR_FILENO));
    // J points at once share the memory: each one's default budget is its share.
    setenv(kMemoryShareVariable, std::to_string(o.jobs).c_str(), 1);
    int status = 0;
    {
        SweepRunner runner(o, grid, table, file, inputs.trace_paths(), [&inputs] { inputs.check_unchanged(); });
        status = runner.run(todo, progress);
    }
    progress.finish();
    file.finish(table);
    if (sweep_stop_signal() != 0 || status != 0) {
        made.keep();  // the points recorded so far stay, to resume
        return status;
    }
    std::string first_reason;
    if (every_point_refused(table, first_reason)) {
        if (!existing) {  // a sweep that never ran a point leaves nothing behind (the directories it made go too)
            std::error_code ignored;
            fs::remove(table_path(o.out_dir), ignored);
            fs::remove(manifest_path(o.out_dir), ignored);
            fs::remove(points_dir(o.out_dir), ignored);  // only if empty
        }
        throw InputError("every point was refused; the first, " + first_reason);
    }
    made.keep();
    status = write_figures(o.out_dir, grid, table, "cdvp sweep", o.quiet, o.plots);
    if (status == 0 && !o.quiet) print_summary(o.out_dir, table, todo.size());
    return status;
}

}  // namespace

int sweep_command(int argc, char** argv) {
    const int status = exit_status_of("cdvp sweep", [&] {
        const std::optional<SweepOptions> options = parse_sweep_options(argc, argv);
        return options ? run_sweep(*options) : print_to_stdout("cdvp sweep", sweep_help());
    });
    if (const int signal_number = sweep_stop_signal(); signal_number != 0) {
        // Every temporary is gone (the points removed theirs); end as the
        // signal would have ended the sweep.
        std::signal(signal_number, SIG_DFL);
        raise(signal_number);
        return 128 + signal_number;
    }
    return status;
}

}  // namespace cdvp
