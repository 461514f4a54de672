#include "sw/study/sweep.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/common/input_path.h"
#include "models/common/pinned_files.h"
#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/directory_lock.h"
#include "sw/study/sweep_figures.h"
#include "sw/study/sweep_manifest.h"
#include "sw/run/exit_codes.h"
#include "sw/run/run_arguments.h"
#include "sw/run/software_timing.h"
#include "sw/study/sweep_software_timings.h"
#include "sw/study/sweep_runner.h"
#include "sw/study/sweep_state.h"
#include "sw/run/version.h"

namespace cdvp {

namespace {

namespace fs = std::filesystem;

// The files the points read, each as the points see it (a pipe spooled once)
// and its digest; and a check, after each point, that none has changed since.
class SweepInputs {
public:
    SweepInputs(const std::vector<NamedInput>& named, const InputLimits& limits,
                const std::function<nlohmann::json(const NamedInput&, const std::string&)>& facts) {
        for (const NamedInput& input : named) {
            std::string path = input.path;
            if (input.option == "--trace") {
                if (spools_.count(input.value) == 0) {
                    spools_.emplace(std::piecewise_construct, std::forward_as_tuple(input.value),
                                    std::forward_as_tuple(input.value, limits));
                }
                path = spools_.at(input.value).path();
                trace_paths_[input.value] = path;
            }
            struct stat before {};
            const bool regular = stat(path.c_str(), &before) == 0 && S_ISREG(before.st_mode);
            if (regular && input.option != "--trace" && before.st_size <= kMaxPinnedBytes) {
                // Read once: the digest covers exactly the text the points in this process read.
                // Read as every input file is: one swapped for a FIFO since the stat is refused, not waited on.
                std::optional<std::string> text;
                try {
                    text = read_input_file({path, "a file the sweep's points read", std::size_t{kMaxPinnedBytes}});
                } catch (const InputError& e) {
                    throw InputError(input.option + ": " + e.what());
                }
                digests_.push_back(digest_text(input.option, input.value, path, *text));
                if (facts) digests_.back().facts = facts(input, *text);
                pins_.pin(path, std::move(*text));
            } else {
                digests_.push_back(digest_input(input.option, input.value, path));
            }
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
    static constexpr off_t kMaxPinnedBytes = 1 << 20;  // a small file's bound (read_small_file's)
    struct Watched {
        SweepInput input;
        struct stat status;
    };
    std::map<std::string, TraceSpool> spools_;
    std::map<std::string, std::string> trace_paths_;
    std::vector<SweepInput> digests_;
    std::vector<Watched> watched_;
    PinnedFiles pins_;
};

// Temporaries left by a killed sweep or point (*.part-*): under the lock no
// one else writes them.
void remove_stale_temporaries(const std::string& dir) {
    for (const std::string& where : {dir, points_dir(dir), software_timings_dir(dir)}) {
        std::error_code error;
        for (const auto& entry : fs::directory_iterator(where, error)) {
            if (entry.is_regular_file() && entry.path().filename().string().find(".part-") != std::string::npos) {
                fs::remove(entry.path(), error);
            }
        }
    }
}

// Refuses an OUT that holds another sweep, another shard of this one, or
// files that are no sweep's, naming OUT and the shard as the face does
// (--out, out=).
void check_out_dir(const std::string& out, const std::optional<Manifest>& existing, const Manifest& wanted,
                   const SettingNames& names) {
    const std::string dir = path_text(out), out_name = names.input("out");
    if (existing) {
        if (const std::optional<SweepDifference> other = difference(*existing, wanted, &names)) {
            if (other->input_changed) {
                throw InputError(out_name + ": " + dir + ": " + other->what + ": restore it to resume, or give a new " +
                                 out_name);
            }
            throw InputError(out_name + ": " + dir + " holds another sweep (" + other->what + "); give a new " +
                             out_name + ", or the same command to resume it");
        }
        if (existing->shard.text() != wanted.shard.text()) {
            throw InputError(out_name + ": " + dir + " holds shard " + existing->shard.text() + " of this sweep, not " +
                             wanted.shard.text() + "; give the same " + names.input("shard") + ", or a new " + out_name);
        }
        return;
    }
    // What a sweep killed before its manifest was written leaves (its empty
    // directories, a temporary) is no other sweep's: it starts over there.
    std::vector<std::string> held;
    for (const std::string& name : directory_contents(out)) {
        const fs::path path = fs::path(out) / name;
        std::error_code error;
        const bool own_empty_directory = (path == fs::path(points_dir(out)) || path == fs::path(software_timings_dir(out))) &&
                                         fs::is_directory(path, error) && fs::is_empty(path, error);
        if (!own_empty_directory && name.find(".part-") == std::string::npos) held.push_back(name);
    }
    if (!held.empty()) {
        throw InputError(out_name + ": " + dir + " holds " + excerpt(held.front()) +
                         (held.size() > 1 ? " and " + std::to_string(held.size() - 1) + " more" : std::string()) +
                         " but no sweep.json: not a sweep's directory, or one whose manifest is gone; give a new or "
                         "empty " + out_name);
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

// The points of this shard, and those of them neither the table nor the
// gathered sweep (of a task: SweepSpec::gathered_into) holds yet.
std::vector<std::size_t> points_to_run(const Grid& grid, const SweepSpec& o, const SweepTable& table, std::size_t& in_shard) {
    static const std::vector<std::size_t> none;
    const std::vector<std::size_t>& held = o.gathered_into ? o.gathered_into->held : none;
    std::vector<std::size_t> todo;
    in_shard = 0;
    for (std::size_t index = 0; index < grid.size(); ++index) {
        if (!o.shard.runs(index)) continue;
        ++in_shard;
        if (!table.has(index) && !std::binary_search(held.begin(), held.end(), index)) todo.push_back(index);
    }
    return todo;
}

// A task's points share the gathered sweep's software timings, unless a
// directory (or none) was named for them.
SweepSpec sharing_gathered_timings(SweepSpec spec) {
    if (spec.gathered_into && !spec.software_timings_given && !spec.software_timings.empty()) {
        spec.software_timings = software_timings_dir(spec.gathered_into->dir);
    }
    return spec;
}

// A sweep's OUT open as run_sweep and prepare_sweep need it: locked, its
// manifest and every row kept checked (or, with rerun_invalid, the rows that
// do not match left out), the manifest written when new, the directories
// made and the table open for appending.
struct OpenSweep {
    explicit OpenSweep(const SweepSpec& o)
        : grid(o.axes), inputs(o.inputs, o.trace_limits, o.input_facts), out(o.out_dir), table(grid) {
        // Shards of one sweep each keep OUT/software unless one directory is named for all.
        const std::string timings_named = o.software_timings_given || o.software_timings.empty() ? o.software_timings
                                                                                                  : "OUT/software";
        const Manifest wanted{grid.axes(), to_arguments(o.run), inputs.digests(), o.shard, kCdvpVersion, o.record, timings_named};
        existing = read_manifest(manifest_path(o.out_dir));
        check_out_dir(o.out_dir, existing, wanted, *o.run.settings.names);
        remove_stale_temporaries(o.out_dir);
        const TableRead read = read_table(o.out_dir, grid, o.shard, table, o.rerun_invalid, o.record);
        if (!o.quiet) {
            for (const std::string& invalid : read.invalid) std::cerr << o.program << ": runs again: " << invalid << '\n';
            if (read.torn) std::cerr << o.program << ": " << table_path(o.out_dir) << ": its last row was cut short; the point runs again\n";
        }
        // The rows kept divided by the timings there: the points to run must too.
        if (!o.software_timings.empty()) {
            if (const std::optional<std::string> changed = check_software_timings(o.software_timings, table)) {
                throw InputError(*changed);
            }
        }
        out.made().create(points_dir(o.out_dir));
        if (!o.software_timings.empty()) out.made().create(o.software_timings);
        if (!existing) commit_text_file(manifest_path(o.out_dir), wanted.to_json().dump(2) + "\n", "--out");
        file.emplace(table_path(o.out_dir), table, read.rewrite);
    }

    // In this order: the grid and the inputs are checked before OUT is made
    // and locked, and the table file is closed before the lock goes.
    const Grid grid;
    const SweepInputs inputs;
    LockedOutDirectory out;
    SweepTable table;
    std::optional<Manifest> existing;
    std::optional<TableFile> file;
};

SweepOutcome outcome_of(const SweepTable& table, std::size_t run_now) {
    SweepOutcome outcome;
    outcome.points = table.size();
    outcome.run_now = run_now;
    table.for_each([&](std::size_t, const RowView& row) {
        const std::string status = row.get("status");
        if (status == "failed" && outcome.first_failure.empty()) {
            outcome.first_failure = row.get("point") + ": " + row.get("reason");
        }
        (status == "ok"        ? outcome.ok
         : status == "refused" ? outcome.refused
         : status == "failed"  ? outcome.failed
                               : outcome.faulted) += 1;
    });
    return outcome;
}

}  // namespace

SweepOutcome run_sweep(const SweepSpec& given, SweepObserver* observer) {
    SweepObserver silent;
    SweepObserver& told = observer != nullptr ? *observer : silent;
    const SweepSpec o = sharing_gathered_timings(given);
    OpenSweep open(o);
    const Grid& grid = open.grid;
    SweepTable& table = open.table;
    TableFile& file = *open.file;
    CreatedDirectories& made = open.out.made();
    const std::optional<Manifest>& existing = open.existing;
    std::size_t in_shard = 0;
    const std::vector<std::size_t> todo = points_to_run(grid, o, table, in_shard);
    told.started(in_shard, in_shard - todo.size());
    // J points at once share the memory: each one's default budget is its share.
    setenv(kMemoryShareVariable, std::to_string(o.jobs).c_str(), 1);
    SweepOutcome outcome;
    {
        const SweepInputs& inputs = open.inputs;
        SweepRunner runner(o, grid, table, file, inputs.trace_paths(), [&inputs] { inputs.check_unchanged(); });
        outcome.status = runner.run(todo, told);
    }
    told.points_ended();
    file.finish(table);
    if (sweep_stop_signal() != 0 || outcome.status != 0) {
        made.keep();  // the points recorded so far stay, to resume
        return outcome;
    }
    std::string first_reason;
    if (!o.gathered_into && every_point_refused(table, first_reason)) {
        if (!existing) {  // a sweep that never ran a point leaves nothing behind (the directories it made go too)
            std::error_code ignored;
            fs::remove(table_path(o.out_dir), ignored);
            fs::remove(manifest_path(o.out_dir), ignored);
            fs::remove(points_dir(o.out_dir), ignored);  // only if empty
            if (!o.software_timings.empty()) fs::remove(o.software_timings, ignored);  // only if empty
        }
        throw InputError("every point was refused; the first, " + first_reason);
    }
    made.keep();
    std::string answer;
    const int status = write_figures(o.out_dir, grid, table, o.program, o.quiet, o.plots, &answer);
    outcome = outcome_of(table, todo.size());
    outcome.answer = answer;
    outcome.status = status != 0 ? status : outcome.failed > 0 ? kExitInternal : 0;
    return outcome;
}

PreparedSweep prepare_sweep(const SweepSpec& o) {
    OpenSweep open(o);
    open.file->finish(open.table);
    open.out.made().keep();
    PreparedSweep prepared;
    prepared.grid_points = open.grid.size();
    prepared.began_now = !open.existing;
    open.table.for_each([&](std::size_t index, const RowView&) { prepared.held.push_back(index); });
    return prepared;
}

}  // namespace cdvp
