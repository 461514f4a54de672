// One run in this process: a RunSpec's settings layered and checked, its
// budgets held before any work, its frames simulated on the platform at the
// level the settings choose, every frame's pairs checked against the float32
// reference, the software baselines timed beside them, and its outputs
// committed all together or not at all. `cdvp run` and `cdvp bullet` parse
// their command lines into a RunSpec and call this; a sweep's points at the
// analytic level and the Python module call it too.
//
// SystemC elaborates a design once a process: a run on the SystemC platform
// (every level but analytic, and Bullet's worlds) may come once a process,
// and RunContext::kernel_free refuses such a run, doing nothing, so that a
// caller running many (a sweep, Python) sends it to a child instead.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "sw/run/run_report.h"
#include "sw/run/run_spec.h"

namespace cdvp {

struct LevelChoice;
struct RunMemo;

// Told how a run goes. The command line prints; a sweep keeps what a point
// said; a Bullet run adds its section (bullet_worlds.h).
class RunObserver {
public:
    virtual ~RunObserver() = default;
    // After each frame simulated and each frame of a later baseline run (--repeat).
    virtual void frame_done(std::size_t done, std::size_t total) { (void)done, (void)total; }
    // A note for the user that is no failure (an uncalibrated host factor).
    virtual void note(const std::string& line) { (void)line; }
    // After the last frame, before the report's summary: sections the report
    // carries after it ({"bullet": ...} for Bullet's worlds), and the native
    // time they took added to `wall`.
    virtual nlohmann::json sections(RunWallTimes& wall) {
        (void)wall;
        return nlohmann::json::object();
    }
    // The summary for standard output, from what the run saw (and, at the
    // auto level, what it chose); committed with the files. Only asked for
    // when RunOutputs::summary.
    virtual std::string summary(const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall,
                                const LevelChoice* choice) {
        (void)run, (void)totals, (void)wall, (void)choice;
        return {};
    }
};

// A decorator: passes everything on to another observer.
class ForwardingObserver : public RunObserver {
public:
    explicit ForwardingObserver(RunObserver& next) : next_(next) {}
    void frame_done(std::size_t done, std::size_t total) override { next_.frame_done(done, total); }
    void note(const std::string& line) override { next_.note(line); }
    nlohmann::json sections(RunWallTimes& wall) override { return next_.sections(wall); }
    std::string summary(const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall,
                        const LevelChoice* choice) override {
        return next_.summary(run, totals, wall, choice);
    }

private:
    RunObserver& next_;
};

struct RunContext {
    // Only a run that elaborates no SystemC kernel (the analytic level) is
    // run; any other comes back with RunOutcome::ran false, nothing done.
    bool kernel_free = false;
    RunMemo* memo = nullptr;          // pairs and scenes kept across runs (sw/run/run_memo.h)
    nlohmann::json* report = nullptr; // the report's frames and summary kept here, not written
};

struct RunOutcome {
    bool ran = true;          // false: RunContext::kernel_free and the run needs a kernel
    int status = 0;           // sw/run/exit_codes.h: 0 done, 2 bad input, 3 device fault, 4 system, 1 internal
    std::string message;      // the one line when status is not 0, without a program's name
};

RunOutcome run(const RunSpec& spec, RunObserver& observer, const RunContext& context = {});

}  // namespace cdvp
