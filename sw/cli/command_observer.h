// How a command of the command line watches its run: a progress line on a
// terminal, notes on stderr under the command's name, and the summary it
// prints (sw/cli/run_summary.cpp).
#pragma once

#include <chrono>
#include <string>

#include "sw/run/run.h"

namespace cdvp {

// The short table printed after a run (run_summary.cpp).
void print_summary(std::ostream& out, const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall);

class CommandObserver : public RunObserver {
public:
    // program: "cdvp run"; progress: a progress line on stderr while the run
    // goes (when stderr is a terminal).
    CommandObserver(std::string program, bool progress);
    void frame_done(std::size_t done, std::size_t total) override;
    void note(const std::string& line) override;
    std::string summary(const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall,
                        const LevelChoice* choice) override;

private:
    std::string program_;
    bool progress_;
    std::chrono::steady_clock::time_point last_{};
};

// A run's outcome as the command ends: its one line on stderr under the
// program's name when it failed, and its exit status.
int command_status(const std::string& program, const RunOutcome& outcome);

}  // namespace cdvp
