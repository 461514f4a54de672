#include "sw/cli/command_observer.h"

#include <unistd.h>

#include <iostream>
#include <sstream>

#include "platform/level_platform.h"
#include "platform/settings/settings.h"

namespace cdvp {

CommandObserver::CommandObserver(std::string program, bool progress)
    : program_(std::move(program)), progress_(progress && isatty(STDERR_FILENO)) {}

void CommandObserver::frame_done(std::size_t done, std::size_t total) {
    if (!progress_ || total <= 1) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    std::cerr << '\r' << program_ << ": frame " << done << "/" << total << std::flush;
    if (done == total) std::cerr << "\r\033[K" << std::flush;
}

void CommandObserver::note(const std::string& line) { std::cerr << program_ << ": " << line << '\n'; }

std::string CommandObserver::summary(const RunDescription& run, const RunTotals& totals, const RunWallTimes& wall,
                                     const LevelChoice* choice) {
    std::ostringstream text;
    print_summary(text, run, totals, wall);
    if (choice != nullptr) text << choice->words("--" + find_setting("run.max_error_percent")->flag) << '\n';
    return text.str();
}

int command_status(const std::string& program, const RunOutcome& outcome) {
    if (outcome.status != 0) std::cerr << program << ": " << outcome.message << '\n';
    return outcome.status;
}

}  // namespace cdvp
