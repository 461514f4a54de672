// A sweep: every point of a grid run as `cdvp run` in a child process, J at a
// time (or in this process, at the analytic level), gathered into OUT/sweep.csv (one row per point, appended and synced as
// each point ends) with each point's report in OUT/points and the figures the
// table supports. Resumable: the same spec into the same OUT runs only the
// points not done yet, after checking every row kept; another grid, other
// options or a changed input file is refused. One sweep or merge at a time
// writes a directory (docs/sweep.md).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/run/run_spec.h"
#include "sw/scene/input_spool.h"
#include "sw/study/sweep_grid.h"
#include "sw/study/sweep_manifest.h"

namespace cdvp {

// Each running point holds its stderr in memory; 24 at once is more than two
// cores use (several shards spread further).
constexpr unsigned kMaxJobs = 24;

// A file the points read, as the command line names it: the option ("--trace",
// "--board", "--config"), the value given, and the path it is read at.
struct NamedInput {
    std::string option, value, path;
};

struct SweepSpec {
    std::vector<Axis> axes;                // in the order given, named by what they set
    // What every point runs: its settings, frames, baselines and faults, the
    // axes set over it (sw/run/run_arguments.h's set_input). It names no
    // output: each point's report, and whether it prints, are the sweep's.
    RunSpec run;
    std::vector<NamedInput> inputs;        // every file the points read
    std::string out_dir;
    unsigned jobs = 1;                     // 1 to kMaxJobs
    Shard shard;
    bool quiet = false;                    // no notes on stderr
    bool plots = true;                     // false: the CSV and data files only
    bool rerun_invalid = false;            // rows that do not match the grid are run again, not refused
    RecordMode record = RecordMode::kFull; // full: a report a point beside its row; compact: the row only
    InputLimits trace_limits;              // what a trace read from a pipe may hold when it is spooled
    std::string program = "cdvp sweep";    // the name notes and errors are printed under
    std::string cdvp_binary;               // the cdvp the points run; empty: this process's executable
    // Points that elaborate no SystemC kernel (the analytic level) run in
    // this process, one at a time, sharing scenes and pairs (RunMemo);
    // false: every point is a child.
    bool in_process = false;
    // Where the points share their software timings, one a workload
    // (sw/study/software_timing.h; --software-timings): OUT/software unless
    // given; empty: each point times its own.
    std::string software_timings;
    bool software_timings_given = false;  // named by the user, not OUT/software (the manifest says which)
    // What an input file may differ by on a resume (SweepInput::facts), from
    // its text: a host profile's reference times and spreads. Set by the
    // command line, which reads host profiles; empty: nothing.
    std::function<nlohmann::json(const NamedInput& input, const std::string& text)> input_facts;
    // One task of a sweep spread over an executor (cdvp.sweep(executor=)):
    // a shard in a directory of its own whose rows a merge gathers into `dir`,
    // which prepare_sweep made ready. The points `dir` holds already are not
    // run here; the software timings are shared through `dir`'s (this
    // manifest names them OUT/software, as the gathered sweep's does) unless
    // software_timings was given; and rows that are all refused are kept:
    // the gathered sweep refuses as a whole.
    struct GatheredInto {
        std::string dir;
        std::vector<std::size_t> held;  // point indices, ascending
    };
    std::optional<GatheredInto> gathered_into;
};

// Told how a sweep goes: a progress bar on a terminal, a callback in a notebook.
class SweepObserver {
public:
    virtual ~SweepObserver() = default;
    // Before the first point: the points of this shard, and how many of them were done before.
    virtual void started(std::size_t total, std::size_t done) { (void)total, (void)done; }
    // After each point that ended (recorded or not).
    virtual void point_done() {}
    // After the last point, before the figures are drawn.
    virtual void points_ended() {}
};

struct SweepOutcome {
    int status = 0;             // 0, or the exit status the sweep ended with (its reason printed)
    std::size_t points = 0;     // rows in the table
    std::size_t ok = 0, refused = 0, faulted = 0, failed = 0;
    std::size_t run_now = 0;    // points this call ran
    std::string first_failure;  // "POINT: reason" of the first failed row, if any
    // The answer's short form (answer.md's table, a line a scene and N, and
    // the crossovers), once answer.md and answer.csv are written; empty when not.
    std::string answer;
};

// Runs the sweep. Throws InputError (bad OUT, another sweep's OUT, a changed
// input, every point refused) or SystemError; a point that could not be
// written ends the sweep with its status, the points recorded so far kept. A
// point that failed inside cdvp (status 1, or killed by a signal) is recorded
// as failed with its reason and the sweep goes on; the sweep then ends with
// status 1 after its figures, naming the first (SweepOutcome::first_failure).
// A stop signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT) is forwarded
// to the running points and ends the sweep: sweep_stop_signal() says which.
SweepOutcome run_sweep(const SweepSpec& spec, SweepObserver* observer = nullptr);

// What a sweep's OUT held before its points were spread over tasks.
struct PreparedSweep {
    std::size_t grid_points = 0;     // the points of the whole grid
    std::vector<std::size_t> held;   // the indices OUT's table holds, ascending
    bool began_now = false;          // OUT held no sweep before: its manifest was written now
};

// Makes OUT ready as run_sweep does before its first point, running none:
// checks OUT's manifest and every row kept (refusing another sweep, a
// changed input, a row that does not match, as a resume does), writes the
// manifest and the table's header when OUT is new, and makes points/ and
// the software timings' directory. The tasks of a spread sweep then run
// the points OUT lacks (SweepSpec::gathered_into) and a merge gathers them.
PreparedSweep prepare_sweep(const SweepSpec& spec);

// The signal that stopped the last sweep (forwarded to its points), or 0.
int sweep_stop_signal();

}  // namespace cdvp
