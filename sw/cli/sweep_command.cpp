#include "sw/cli/sweep_command.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/common/user_text.h"
#include "sw/cli/child_runs.h"
#include "sw/cli/run_command.h"
#include "sw/cli/run_options.h"
#include "sw/cli/sweep_files.h"
#include "sw/cli/sweep_names.h"
#include "sw/cli/sweep_options.h"
#include "sw/cli/sweep_progress.h"

namespace cdvp {

namespace {

// Signals that stop a sweep: forwarded to the running points, which remove
// their temporaries; the sweep records the points that still finish, then
// ends by the same signal.
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
volatile std::sig_atomic_t g_stop_signal = 0;
volatile pid_t g_running[kMaxJobs];

extern "C" void stop_sweep(int signal_number) {
    g_stop_signal = signal_number;
    for (const volatile pid_t& pid : g_running) {
        if (pid > 0) kill(pid, signal_number);  // async-signal-safe
    }
}

class StopSignalsHandled {
public:
    StopSignalsHandled() {
        for (std::size_t k = 0; k < std::size(kStopSignals); ++k) {
            struct sigaction action {};
            action.sa_handler = stop_sweep;  // no SA_RESTART: waitpid returns EINTR
            sigemptyset(&action.sa_mask);
            sigaction(kStopSignals[k], nullptr, &previous_[k]);
            if (previous_[k].sa_handler != SIG_IGN) sigaction(kStopSignals[k], &action, nullptr);
        }
    }
    ~StopSignalsHandled() {
        for (std::size_t k = 0; k < std::size(kStopSignals); ++k) sigaction(kStopSignals[k], &previous_[k], nullptr);
    }

private:
    struct sigaction previous_[std::size(kStopSignals)] {};
};

// A point running in a child process.
struct Slot {
    pid_t pid = 0;
    Point point;
    std::unique_ptr<ScratchFile> errors;  // the child's stderr
    std::chrono::steady_clock::time_point started;
};

// The child's one-line reason, without "cdvp run: ".
std::string reason_of(const std::string& stderr_text, const std::map<std::string, TraceSpool>& spools) {
    std::string line = stderr_text.substr(0, stderr_text.find('\n'));
    if (line.rfind("cdvp run: ", 0) == 0) line = line.substr(10);
    for (const auto& [name, spool] : spools) line = spool.restore_names(line);
    return printable(line);
}

class Sweep {
public:
    Sweep(const SweepOptions& options, const Grid& grid, SweepTable& table)
        : o_(options), grid_(grid), table_(table), self_(self_path()) {
        // Traces from pipes are read once, each point reads the copy.
        for (const Axis& axis : grid.axes()) {
            if (axis.name != "trace") continue;
            for (const std::string& value : axis.values) spools_.emplace(value, value);
        }
        slots_.resize(o_.jobs);
        for (Slot& slot : slots_) slot.errors = std::make_unique<ScratchFile>(".err");
    }

    // A sweep left by an exception stops its points and waits for them, so
    // none outlives it.
    ~Sweep() {
        signal_running(SIGTERM);
        for (Slot& slot : slots_) {
            if (slot.pid > 0) wait_child(slot.pid);
        }
        for (volatile pid_t& pid : g_running) pid = 0;
    }
    Sweep(const Sweep&) = delete;
    Sweep& operator=(const Sweep&) = delete;

    // Runs the points not in the table yet; 0, or 1 with the message
    // printed when a point failed inside cdvp.
    int run(const std::vector<std::size_t>& todo, SweepProgress& progress) {
        const StopSignalsHandled handled;
        std::size_t next = 0;
        int status = 0;
        while (true) {
            for (std::size_t k = 0; k < slots_.size() && next < todo.size() && g_stop_signal == 0 && !failing_; ++k) {
                if (slots_[k].pid == 0) launch(k, grid_.point(todo[next++]));
            }
            if (running() == 0) break;
            int wait_status = 0;
            const pid_t pid = waitpid(-1, &wait_status, 0);
            if (pid < 0) {
                if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
                if (g_stop_signal != 0) signal_running(g_stop_signal);
                continue;
            }
            for (std::size_t k = 0; k < slots_.size(); ++k) {
                if (slots_[k].pid != pid) continue;
                slots_[k].pid = 0;
                g_running[k] = 0;
                if (finish(slots_[k], wait_status) != 0 && !failing_) {
                    failing_ = true;  // the others are stopped, and their ends go unreported
                    status = kExitInternal;
                    signal_running(SIGTERM);
                }
                progress.point_done();
            }
        }
        return status;
    }

private:
    std::size_t running() const {
        std::size_t n = 0;
        for (const Slot& slot : slots_) n += slot.pid != 0;
        return n;
    }
    void signal_running(int signal_number) {
        for (const Slot& slot : slots_) {
            if (slot.pid > 0) kill(slot.pid, signal_number);
        }
    }

    void launch(std::size_t k, const Point& point) {
        std::vector<std::string> args{self_, "run"};
        args.insert(args.end(), o_.run_options.begin(), o_.run_options.end());
        std::vector<std::string> axes = grid_.run_arguments(point);
        for (std::size_t a = 0; a + 1 < axes.size(); ++a) {
            if (axes[a] == "--trace") axes[a + 1] = spools_.at(axes[a + 1]).path();
        }
        args.insert(args.end(), axes.begin(), axes.end());
        args.insert(args.end(), {"--report", report_path(o_.out_dir, point), "-q"});
        Slot& slot = slots_[k];
        slot.point = point;
        slot.started = std::chrono::steady_clock::now();
        slot.pid = start_child(args, slot.errors->path());
        g_running[k] = slot.pid;
    }

    // Records the point's row (committing the CSV); 1 when it failed inside cdvp.
    int finish(const Slot& slot, int wait_status) {
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - slot.started).count();
        const std::string& id = slot.point.id;
        if (WIFSIGNALED(wait_status)) {
            if (g_stop_signal != 0 || failing_) return 0;  // stopped with the sweep: run again on resume
            std::cerr << "cdvp sweep: point " << id << ": cdvp run was killed by signal " << WTERMSIG(wait_status) << '\n';
            return 1;
        }
        const int code = WEXITSTATUS(wait_status);
        const std::string reason = reason_of(slurp(slot.errors->path()), spools_);
        if (code == kExitDone) {
            const std::string path = report_path(o_.out_dir, slot.point);
            table_.add(slot.point.index, report_row(grid_, slot.point, nlohmann::json::parse(slurp(path)), wall));
        } else if (code == kExitBadInput || code == kExitDeviceFault) {
            const PointStatus status = code == kExitBadInput ? PointStatus::kRefused : PointStatus::kFault;
            table_.add(slot.point.index, failed_row(grid_, slot.point, status, reason, wall));
        } else {
            std::cerr << "cdvp sweep: point " << id << ": cdvp run failed (status " << code << "): " << reason << '\n';
            return 1;
        }
        commit_text_file(table_path(o_.out_dir), table_.csv(), "--out");
        return 0;
    }

    const SweepOptions& o_;
    const Grid& grid_;
    SweepTable& table_;
    std::string self_;
    std::map<std::string, TraceSpool> spools_;
    std::vector<Slot> slots_;
    bool failing_ = false;  // a point failed inside cdvp: no new points start
};

// User and system CPU time of the process or of its waited-for children.
std::string cpu_seconds(int who) {
    struct rusage usage {};
    getrusage(who, &usage);
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; };
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds(usage.ru_utime) + seconds(usage.ru_stime));
    return text;
}

// Every row refused (a typo in an option, say): the first reason, and the
// files of a sweep that had no rows before are removed again.
bool every_point_refused(const SweepTable& table, std::string& first) {
    if (table.rows().empty()) return false;
    for (const auto& [index, row] : table.rows()) {
        if (row.at("status") != "refused") return false;
    }
    const Row& row = table.rows().begin()->second;
    first = row.at("point") + ": " + (row.count("reason") ? row.at("reason") : "");
    return true;
}

int run_sweep(const SweepOptions& o) {
    const Grid grid(o.axes);
    check_axis_names(o.axes, axis_names(run_options_help(), self_path()));
    // A different grid, other options or another shard into the same --out
    // are refused: the rows would not belong together.
    const nlohmann::json wanted = manifest(grid, o.run_options, o.shard);
    const std::optional<nlohmann::json> existing = read_manifest(o.out_dir);
    if (existing && (!same_sweep(*existing, wanted) || existing->at("shard") != wanted.at("shard"))) {
        throw InputError("--out: " + excerpt(o.out_dir) + " holds another sweep (" +
                         (same_sweep(*existing, wanted) ? "shard " + existing->at("shard").get<std::string>()
                                                        : std::string("other axes or options")) +
                         "); give a new --out, or the same command to resume it");
    }
    struct stat out_status {};
    if (stat(o.out_dir.c_str(), &out_status) == 0 && !S_ISDIR(out_status.st_mode)) {
        throw InputError("--out: " + excerpt(o.out_dir) + ": expected a directory");
    }
    SweepTable table(grid);
    read_table(o.out_dir, table);
    const bool fresh = table.rows().empty();
    std::vector<std::size_t> todo;
    std::size_t in_shard = 0;
    for (std::size_t index = 0; index < grid.size(); ++index) {
        if (!o.shard.runs(index)) continue;
        ++in_shard;
        if (!table.has(index)) todo.push_back(index);
    }

    CreatedDirectories made;
    made.create(o.out_dir);
    made.create(points_dir(o.out_dir));
    if (!existing) commit_text_file(manifest_path(o.out_dir), wanted.dump(2) + "\n", "--out");
    SweepProgress progress(in_shard, in_shard - todo.size(), !o.quiet && isatty(STDERR_FILENO));
    int status = 0;
    {
        Sweep sweep(o, grid, table);
        status = sweep.run(todo, progress);
    }
    progress.finish();
    if (g_stop_signal != 0 || status != 0) {
        made.keep();  // the points recorded so far stay, to resume
        return status;
    }
    std::string first_reason;
    if (every_point_refused(table, first_reason)) {
        if (fresh) {
            std::error_code ignored;
            std::filesystem::remove(table_path(o.out_dir), ignored);
            std::filesystem::remove(manifest_path(o.out_dir), ignored);
            std::filesystem::remove(points_dir(o.out_dir), ignored);  // only if empty
        }
        throw InputError("every point was refused; the first, " + first_reason);
    }
    made.keep();
    commit_text_file(table_path(o.out_dir), table.csv(), "--out");
    if (o.plots) status = write_figures(o.out_dir, grid, table, "cdvp sweep", o.quiet);
    if (status == 0 && !o.quiet) {
        std::size_t counts[3] = {};
        for (const auto& [index, row] : table.rows()) {
            counts[row.at("status") == "ok" ? 0 : row.at("status") == "refused" ? 1 : 2] += 1;
        }
        std::cout << "cdvp sweep: " << table.rows().size() << " points in " << table_path(o.out_dir) << ": "
                  << counts[0] << " ok, " << counts[1] << " refused, " << counts[2] << " faulted ("
                  << todo.size() << " run now; CPU time " << cpu_seconds(RUSAGE_SELF) << " s in the sweep, "
                  << cpu_seconds(RUSAGE_CHILDREN) << " s in its points and plots)\n";
    }
    return status;
}

}  // namespace

int sweep_command(int argc, char** argv) {
    const int status = exit_status_of("cdvp sweep", [&] {
        const std::optional<SweepOptions> options = parse_sweep_options(argc, argv);
        return options ? run_sweep(*options) : print_to_stdout("cdvp sweep", sweep_help());
    });
    if (const int signal_number = g_stop_signal; signal_number != 0) {
        // Every temporary is gone (the scratch files with the sweep); end as
        // the signal would have ended the sweep.
        std::signal(signal_number, SIG_DFL);
        raise(signal_number);
        return 128 + signal_number;
    }
    return status;
}

}  // namespace cdvp
