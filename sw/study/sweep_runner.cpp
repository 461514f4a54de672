#include "sw/study/sweep_runner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <chrono>
#include <csignal>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "models/common/user_text.h"
#include "sw/output/output_cleanup.h"
#include "sw/output/output_file.h"
#include "sw/run/exit_codes.h"
#include "sw/run/run.h"
#include "sw/run/run_arguments.h"

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

// The child's one-line reason, without "cdvp run: ", with the user's names
// for spooled traces.
std::string reason_of(const std::string& stderr_text, const std::map<std::string, std::string>& trace_paths) {
    std::string line = stderr_text.substr(0, stderr_text.find('\n'));
    if (line.rfind("cdvp run: ", 0) == 0) line = line.substr(10);
    for (const auto& [value, path] : trace_paths) {
        for (std::size_t at; path != value && (at = line.find(path)) != std::string::npos;) line.replace(at, path.size(), value);
    }
    return printable(line);
}

}  // namespace

int sweep_stop_signal() { return g_stop_signal; }

// A point running in a child process.
struct SweepRunner::Slot {
    pid_t pid = 0;
    Point point;
    CapturedOutput errors{"cdvp-point-stderr"};
    std::chrono::steady_clock::time_point started;
    int wait_status = 0;
};

SweepRunner::SweepRunner(const SweepSpec& spec, const Grid& grid, SweepTable& table, TableFile& file,
                         const std::map<std::string, std::string>& trace_paths, std::function<void()> check_inputs)
    : o_(spec), grid_(grid), table_(table), file_(file), trace_paths_(trace_paths),
      check_inputs_(std::move(check_inputs)), self_(spec.cdvp_binary.empty() ? self_path() : spec.cdvp_binary) {
    if (o_.in_process) memo_ = std::make_unique<RunMemo>();
    for (unsigned k = 0; k < o_.jobs; ++k) slots_.push_back(std::make_unique<Slot>());
}

// A runner left by an exception stops its points and waits for them, so
// none outlives it.
SweepRunner::~SweepRunner() {
    signal_running(SIGTERM);
    for (const auto& slot : slots_) {
        if (slot->pid > 0) wait_child(slot->pid);
    }
    for (volatile pid_t& pid : g_running) pid = 0;
}

int SweepRunner::run(const std::vector<std::size_t>& todo, SweepObserver& observer) {
    // The temporaries' handlers first, so that the stop handlers below stay
    // in place while points run in process (their outputs are committed or
    // discarded before the sweep ends by the signal).
    if (o_.in_process) TemporaryRegistry::install_handlers();
    g_stop_signal = 0;  // a process may run many sweeps (Python): none stops the next
    const StopSignalsHandled handled;
    std::size_t next = 0;
    const auto go_on = [&] { return next < todo.size() && g_stop_signal == 0 && failing_ == 0; };
    while (true) {
        for (std::size_t k = 0; k < slots_.size(); ++k) {
            while (slots_[k]->pid == 0 && go_on()) {
                const Point point = grid_.point(todo[next++]);
                if (!run_in_process(point, observer)) launch(*slots_[k], k, point);
            }
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
            Slot& slot = *slots_[k];
            if (slot.pid != pid) continue;
            slot.pid = 0;
            slot.wait_status = wait_status;
            g_running[k] = 0;
            const int status = finish(slot);
            if (status != 0 && failing_ == 0) failing_ = status;  // no new points; the running ones may still end well
            observer.point_done();
        }
    }
    file_.sync();
    return failing_;
}

bool SweepRunner::run_in_process(const Point& point, SweepObserver& observer) {
    if (!o_.in_process) return false;
    const auto started = std::chrono::steady_clock::now();
    const bool compact = o_.record == RecordMode::kCompact;
    const std::string report = report_file(point);
    nlohmann::json in_memory;
    RunObserver quiet;  // a point prints nothing: its row says what it did
    RunContext context;
    context.kernel_free = true;
    context.memo = memo_.get();
    context.report = compact ? &in_memory : nullptr;
    const RunOutcome outcome = cdvp::run(point_spec(point, compact ? nullptr : &report), quiet, context);
    if (!outcome.ran) return false;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const int status = record(point, outcome.status, reason_of(outcome.message, trace_paths_), wall, false,
                              compact ? &in_memory : nullptr);
    if (status != 0 && failing_ == 0) failing_ = status;
    // Rows of fast points are synced together, a few times a second.
    if (std::chrono::steady_clock::now() - last_sync_ > std::chrono::milliseconds(250)) {
        file_.sync();
        last_sync_ = std::chrono::steady_clock::now();
    }
    observer.point_done();
    return true;
}

std::size_t SweepRunner::running() const {
    std::size_t n = 0;
    for (const auto& slot : slots_) n += slot->pid != 0;
    return n;
}

void SweepRunner::signal_running(int signal_number) {
    for (const auto& slot : slots_) {
        if (slot->pid > 0) kill(slot->pid, signal_number);
    }
}

RunSpec SweepRunner::point_spec(const Point& point, const std::string* report) const {
    RunSpec spec = o_.run;
    for (std::size_t a = 0; a < grid_.axes().size(); ++a) {
        const Axis& axis = grid_.axes()[a];
        // A trace is read where the sweep spooled it (a pipe's copy).
        const std::string& value = axis.key == "trace" ? trace_paths_.at(point.values[a]) : point.values[a];
        set_input(spec, axis.key, value, !axis.flag.empty());
    }
    if (report != nullptr) spec.outputs.report = *report;
    if (!o_.software_timings.empty()) spec.software_timings = o_.software_timings;
    spec.outputs.summary = false;
    return spec;
}

std::string SweepRunner::report_file(const Point& point) const {
    const std::string path = report_path(o_.out_dir, point);
    // A name a killed sweep's leftovers are removed by (*.part-*) on resume.
    return o_.record == RecordMode::kCompact ? path + ".part-compact" : path;
}

void SweepRunner::launch(Slot& slot, std::size_t k, const Point& point) {
    const std::string report = report_file(point);
    const RunSpec spec = point_spec(point, &report);
    std::vector<std::string> args{self_, command_of(spec)};
    for (std::string& arg : to_arguments(spec)) args.push_back(std::move(arg));
    slot.point = point;
    slot.errors.clear();
    slot.started = std::chrono::steady_clock::now();
    ChildStreams streams;
    streams.err = slot.errors.fd();
    for (const auto& [value, path] : trace_paths_) {
        if (path.rfind("/proc/self/fd/", 0) == 0) streams.inherited.push_back(std::stoi(path.substr(14)));
    }
    slot.pid = start_child(args, streams);
    g_running[k] = slot.pid;
}

// Records the point's row; 0, or the status that ends the sweep (its reason printed).
int SweepRunner::finish(Slot& slot) {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - slot.started).count();
    if (WIFSIGNALED(slot.wait_status)) {
        remove_temporaries_of(report_file(slot.point));  // SIGKILL leaves them
        if (g_stop_signal != 0 || failing_ != 0) return 0;  // stopped with the sweep: it runs again on resume
        // Killed by something else (the kernel out of memory, say): the row says so and the sweep goes on.
        check_inputs_();
        table_.add(slot.point.index, failed_row(grid_, slot.point, PointStatus::kFailed,
                                                "cdvp run was killed by signal " + std::to_string(WTERMSIG(slot.wait_status)),
                                                wall));
        file_.append(table_, slot.point.index, true);
        return 0;
    }
    return record(slot.point, WEXITSTATUS(slot.wait_status), reason_of(slot.errors.text(64 * 1024), trace_paths_), wall,
                  true);
}

// The row of a point that ended with `code`; 0, or the status that ends the sweep.
int SweepRunner::record(const Point& point, int code, const std::string& reason, double wall, bool sync_now,
                        const nlohmann::json* in_memory) {
    const std::string& id = point.id;
    const std::string report = report_file(point);
    check_inputs_();  // a file changed during the point: its row would not belong to this sweep
    auto fail = [&](int status, const std::string& why) {
        std::cerr << o_.program << ": point " << id << ": " << why << "; the point is not recorded\n";
        return status;
    };
    if (code == kExitDone && in_memory != nullptr) {
        table_.add(point.index, compact_row(grid_, point, *in_memory, wall));
    } else if (code == kExitDone) {
        const std::optional<std::string> text = read_whole_file(report);
        if (!text) return fail(kExitInternal, "cdvp run ended well but its report " + excerpt(report) + " cannot be read: " +
                                                  std::strerror(errno) + " (internal error: a cdvp bug)");
        if (o_.record == RecordMode::kCompact) {
            std::remove(report.c_str());
            table_.add(point.index, compact_row(grid_, point, nlohmann::json::parse(*text), wall));
        } else {
            table_.add(point.index, report_row(grid_, point, *text, wall));
        }
    } else if (code == kExitSystem) {
        return fail(kExitSystem, reason);
    } else if ((code == kExitBadInput || code == kExitDeviceFault) && reason.rfind("--report", 0) == 0) {
        return fail(code, "its report could not be written: " + reason);  // the sweep's own file, not the point's answer
    } else if (code == kExitBadInput || code == kExitDeviceFault) {
        const PointStatus status = code == kExitBadInput ? PointStatus::kRefused : PointStatus::kFault;
        table_.add(point.index, failed_row(grid_, point, status, reason, wall));
    } else {
        // A bug at one point says nothing of the others: its row keeps the reason, and the sweep goes on.
        table_.add(point.index, failed_row(grid_, point, PointStatus::kFailed,
                                           "cdvp run failed (status " + std::to_string(code) + "): " + reason, wall));
    }
    file_.append(table_, point.index, sync_now);
    return 0;
}

}  // namespace cdvp
