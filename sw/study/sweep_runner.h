// Runs a sweep's points as `cdvp run` child processes, J at a time, and
// records each as it ends: a row appended to the table file, synced. A point
// refused (status 2) or faulted (3) is a row; a point whose output the system
// could not write (4), a child that failed inside cdvp (1) or was killed is
// none, and no new point starts: the sweep ends with that status and a rerun
// runs the point again. Children die with the sweep (SIGTERM, even when the
// sweep is killed), and keep their stderr in memory, so a killed sweep leaves
// neither running points nor scratch files.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sw/run/run_memo.h"
#include "sw/study/child_runs.h"
#include "sw/study/sweep.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_state.h"
#include "sw/study/sweep_table.h"

namespace cdvp {

class SweepRunner {
public:
    // 'spools' gives the path the points read each trace value at (a pipe's
    // copy); 'check_inputs' throws InputError when an input file changed.
    SweepRunner(const SweepSpec& spec, const Grid& grid, SweepTable& table, TableFile& file,
                const std::map<std::string, std::string>& trace_paths, std::function<void()> check_inputs);
    ~SweepRunner();
    SweepRunner(const SweepRunner&) = delete;
    SweepRunner& operator=(const SweepRunner&) = delete;

    // Runs the points 'todo'; 0, or the status the sweep ends with, its
    // reason printed.
    int run(const std::vector<std::size_t>& todo, SweepObserver& observer);

private:
    struct Slot;
    // The point's run: the sweep's with the point's axes set over it;
    // `report` names where its report goes (none: kept in memory).
    RunSpec point_spec(const Point& point, const std::string* report) const;
    // Where a point's report is written: its place in OUT/points, or for a
    // compact record a temporary there, read and removed when the point ends.
    std::string report_file(const Point& point) const;
    // Runs the point here when the spec's in_process takes it; false: it needs a child.
    bool run_in_process(const Point& point, SweepObserver& observer);
    void launch(Slot& slot, std::size_t k, const Point& point);
    int finish(Slot& slot);
    // `report`: the point's report held in memory (a compact record run in process).
    int record(const Point& point, int code, const std::string& reason, double wall, bool sync_now,
               const nlohmann::json* report = nullptr);
    std::size_t running() const;
    void signal_running(int signal_number);

    const SweepSpec& o_;
    const Grid& grid_;
    SweepTable& table_;
    TableFile& file_;
    const std::map<std::string, std::string>& trace_paths_;
    std::function<void()> check_inputs_;
    std::string self_;
    std::unique_ptr<RunMemo> memo_;  // what points run in process share
    std::vector<std::unique_ptr<Slot>> slots_;
    std::chrono::steady_clock::time_point last_sync_{};
    int failing_ = 0;  // the status a failed point ends the sweep with: no new points start
};

}  // namespace cdvp
