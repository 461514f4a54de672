#include "sw/study/sweep_merge.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "models/common/input_path.h"
#include "models/common/user_text.h"
#include "sw/study/child_runs.h"
#include "sw/study/directory_lock.h"
#include "sw/study/sweep_figures.h"
#include "sw/study/sweep_manifest.h"
#include "sw/study/sweep_state.h"
#include "sw/run/software_timing.h"
#include "sw/study/sweep_software_timings.h"

#include <iostream>

namespace cdvp {

namespace {

namespace fs = std::filesystem;

// The shards' common manifest, checked: one sweep, one N, each shard once.
Manifest shards_manifest(const std::vector<std::string>& shards) {
    if (shards.empty()) throw InputError("no shard to merge: give at least one sweep directory");
    std::vector<Manifest> manifests;
    std::set<std::string> seen;
    for (const std::string& dir : shards) {
        std::optional<Manifest> m = read_manifest(manifest_path(dir));
        if (!m) throw InputError(path_text(dir) + ": not a sweep directory (no sweep.json)");
        if (!manifests.empty()) {
            if (const std::optional<SweepDifference> other = difference(manifests[0], *m)) {
                throw InputError(path_text(dir) + ": a shard of another sweep than " + path_text(shards[0]) + " (" +
                                 other->what + ")");
            }
            if (m->shard.count != manifests[0].shard.count) {
                throw InputError(path_text(dir) + ": shard " + m->shard.text() + " of a sweep cut in " +
                                 std::to_string(manifests[0].shard.count) + " by " + path_text(shards[0]) +
                                 "; give shards of one --shard K/N");
            }
        }
        if (!seen.insert(m->shard.text()).second) {
            throw InputError(path_text(dir) + ": shard " + m->shard.text() + " is given twice");
        }
        manifests.push_back(std::move(*m));
    }
    Manifest merged = manifests[0];
    merged.shard = Shard{};
    return merged;
}

// A report into the staging directory: a hard link where the file system
// allows one (reports are never written in place, only replaced), else a copy.
void place_report(const std::string& from, const std::string& to) {
    if (link(from.c_str(), to.c_str()) == 0) return;
    const std::optional<std::string> text = read_whole_file(from);
    if (!text) throw_os_error(path_text(from) + ": cannot read", errno);
    const int fd = open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw_os_error("--out: " + path_text(to) + ": cannot write", errno);
    for (std::size_t done = 0; done < text->size();) {
        const ssize_t put = write(fd, text->data() + done, text->size() - done);
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) {
            const int error = errno;
            close(fd);
            throw_os_error("--out: " + path_text(to) + ": cannot write", error);
        }
        done += static_cast<std::size_t>(put);
    }
    if (close(fd) != 0) throw_os_error("--out: " + path_text(to) + ": cannot write", errno);
}

// The staging directory beside OUT, removed with all it holds unless it was
// swapped into place.
class Staging {
public:
    explicit Staging(const std::string& out) {
        const fs::path target = fs::absolute(out);
        path_ = (target.parent_path() / ("." + target.filename().string() + ".merge-" + std::to_string(getpid()))).string();
        std::error_code error;
        fs::remove_all(path_, error);
        if (mkdir(path_.c_str(), 0755) != 0) throw_os_error("--out: " + path_text(path_) + ": cannot create", errno);
        if (mkdir(points_dir(path_).c_str(), 0755) != 0) {
            throw_os_error("--out: " + path_text(points_dir(path_)) + ": cannot create", errno);
        }
    }
    ~Staging() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    Staging(const Staging&) = delete;
    Staging& operator=(const Staging&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Puts the staging directory in OUT's place in one step (the old OUT then
// sits where the staging was, and goes with it).
void swap_into_place(const std::string& staging, const std::string& out) {
    const int staged = open(staging.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (staged >= 0) {
        syncfs(staged);  // every report and table on disk before they are published
        close(staged);
    }
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, out.c_str(), RENAME_EXCHANGE) != 0) {
        throw_os_error("--out: " + excerpt(out) + ": cannot put the merge in place", errno);
    }
}

}  // namespace

MergeOutcome merge_sweeps(const MergeSpec& o) {
    const Manifest merged = shards_manifest(o.shards);
    const Grid grid(merged.axes);
    LockedOutDirectory out(o.out);
    CreatedDirectories& made = out.made();
    const std::optional<Manifest> existing = read_manifest(manifest_path(o.out));
    if (existing ? difference(*existing, merged).has_value() || !existing->shard.whole()
                 : !directory_contents(o.out).empty()) {
        throw InputError("--out: " + path_text(o.out) + ": expected a new or empty directory, or a merge of the same sweep");
    }

    const Staging staging(o.out);
    SweepTable table(grid);
    std::vector<std::string> from(grid.size());  // the directory each point's row came from
    auto take = [&](const std::string& dir, const Shard& shard) {
        SweepTable rows(grid);
        // Every row checked, or refused naming file, line and field.
        if (read_table(dir, grid, shard, rows, false, merged.record).torn) {
            throw InputError(path_text(table_path(dir)) + ": its last row is cut short (its sweep was stopped while "
                             "writing it): run that sweep again to complete it, then merge");
        }
        rows.for_each([&](std::size_t index, const RowView& row) {
            if (table.has(index)) {
                if (row.get(kChecksumColumn) == table.row(index).get(kChecksumColumn)) return;  // merged before
                throw InputError(path_text(dir) + ": point " + std::to_string(index) + " is also in " + path_text(from[index]) +
                                 ", with other results; give each shard once");
            }
            from[index] = dir;
            const Point point = grid.point(index);
            if (row.get("status") == "ok" && merged.record == RecordMode::kFull) place_report(report_path(dir, point), report_path(staging.path(), point));
            table.add(index, rows.point_row(index));
        });
    };
    if (existing) take(o.out, Shard{});
    for (const std::string& dir : o.shards) take(dir, read_manifest(manifest_path(dir))->shard);
    // Each shard's own timings come along, so that the merge resumes as the shards do.
    if (merged.software_timings == "OUT/software") {
        std::vector<std::string> sources = o.shards;
        if (existing) sources.insert(sources.begin(), o.out);
        for (const std::string& dir : sources) {
            for (const std::string& note : merge_software_timings(software_timings_dir(dir), software_timings_dir(staging.path()))) {
                if (!o.quiet) std::cerr << o.program << ": note: " << note << '\n';
            }
        }
    }
    commit_text_file(manifest_path(staging.path()), merged.to_json().dump(2) + "\n", "--out");
    commit_text_file(table_path(staging.path()), table.csv(), "--out");
    MergeOutcome outcome{0, table.size(), grid.size(), {}};
    if ((outcome.status = write_figures(staging.path(), grid, table, o.program, o.quiet, o.plots, &outcome.answer)) != 0) {
        return outcome;
    }
    swap_into_place(staging.path(), o.out);
    made.keep();
    return outcome;
}


}  // namespace cdvp
