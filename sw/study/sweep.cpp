#include "sw/study/sweep.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/common/pinned_files.h"
#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/directory_lock.h"
#include "sw/study/sweep_figures.h"
#include "sw/study/sweep_manifest.h"
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
                std::optional<std::string> text = read_whole_file(path);
                if (!text) throw InputError(input.option + ": " + excerpt(input.value) + ": cannot read: " + std::strerror(errno));
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

// The points of this shard, and those of them the table does not hold yet.
std::vector<std::size_t> points_to_run(const Grid& grid, const Shard& shard, const SweepTable& table, std::size_t& in_shard) {
    std::vector<std::size_t> todo;
    in_shard = 0;
    for (std::size_t index = 0; index < grid.size(); ++index) {
        if (!shard.runs(index)) continue;
        ++in_shard;
        if (!table.has(index)) todo.push_back(index);
    }
    return todo;
}

SweepOutcome outcome_of(const SweepTable& table, std::size_t run_now) {
    SweepOutcome outcome;
    outcome.points = table.size();
    outcome.run_now = run_now;
    table.for_each([&](std::size_t, const RowView& row) {
        const std::string status = row.get("status");
        (status == "ok" ? outcome.ok : status == "refused" ? outcome.refused : outcome.faulted) += 1;
    });
    return outcome;
}

}  // namespace

SweepOutcome run_sweep(const SweepSpec& o, SweepObserver* observer) {
    SweepObserver silent;
    SweepObserver& told = observer != nullptr ? *observer : silent;
    const Grid grid(o.axes);
    const SweepInputs inputs(o.inputs, o.trace_limits, o.input_facts);
    // Shards of one sweep each keep OUT/software unless one directory is named for all.
    const std::string timings_named = o.software_timings_given || o.software_timings.empty() ? o.software_timings
                                                                                              : "OUT/software";
    const Manifest wanted{grid.axes(), to_arguments(o.run), inputs.digests(), o.shard, kCdvpVersion, o.record, timings_named};
    LockedOutDirectory out(o.out_dir);
    CreatedDirectories& made = out.made();
    const std::optional<Manifest> existing = read_manifest(manifest_path(o.out_dir));
    check_out_dir(o.out_dir, existing, wanted);
    remove_stale_temporaries(o.out_dir);

    SweepTable table(grid);
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
    std::size_t in_shard = 0;
    const std::vector<std::size_t> todo = points_to_run(grid, o.shard, table, in_shard);
    made.create(points_dir(o.out_dir));
    if (!o.software_timings.empty()) made.create(o.software_timings);
    if (!existing) commit_text_file(manifest_path(o.out_dir), wanted.to_json().dump(2) + "\n", "--out");
    TableFile file(table_path(o.out_dir), table, read.rewrite);
    told.started(in_shard, in_shard - todo.size());
    // J points at once share the memory: each one's default budget is its share.
    setenv(kMemoryShareVariable, std::to_string(o.jobs).c_str(), 1);
    SweepOutcome outcome;
    {
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
    if (every_point_refused(table, first_reason)) {
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
    const int status = write_figures(o.out_dir, grid, table, o.program, o.quiet, o.plots);
    outcome = outcome_of(table, todo.size());
    outcome.status = status;
    return outcome;
}

}  // namespace cdvp
