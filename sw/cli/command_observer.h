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

// How a command shows its frames' progress on stderr: a line kept in place
// on a terminal (kAuto; nothing when stderr is not one), a line about every
// second with the time left, for whatever captures stderr (kLines), or none.
enum class ProgressMode { kAuto, kLines, kNone };
// "auto", "lines" or "none"; throws InputError naming `flag` otherwise.
ProgressMode progress_mode(const std::string& text, const std::string& flag);

class CommandObserver : public RunObserver {
public:
    // program: "cdvp run"; progress: how its frames' progress shows.
    CommandObserver(std::string program, ProgressMode progress);
    void frame_done(std::size_t done, std::size_t total) override;
    void note(const std::string& line) override;
    std::string summary(const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall,
                        const LevelChoice* choice) override;

private:
    std::string program_;
    ProgressMode progress_;
    std::chrono::steady_clock::time_point start_{}, last_{};
};

// A run's outcome as the command ends: its one line on stderr under the
// program's name when it failed, and its exit status.
int command_status(const std::string& program, const RunOutcome& outcome);

}  // namespace cdvp
