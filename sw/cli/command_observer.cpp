#include "sw/cli/command_observer.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <sstream>

#include "models/common/user_text.h"
#include "platform/level_platform.h"
#include "platform/settings/settings.h"

namespace cdvp {

ProgressMode progress_mode(const std::string& text, const std::string& flag) {
    if (text == "auto") return ProgressMode::kAuto;
    if (text == "lines") return ProgressMode::kLines;
    if (text == "none") return ProgressMode::kNone;
    throw InputError(flag + ": expected auto, lines or none, got '" + excerpt(text) + "'");
}

CommandObserver::CommandObserver(std::string program, ProgressMode progress)
    : program_(std::move(program)),
      progress_(progress == ProgressMode::kAuto && !isatty(STDERR_FILENO) ? ProgressMode::kNone : progress),
      start_(std::chrono::steady_clock::now()) {}

void CommandObserver::frame_done(std::size_t done, std::size_t total) {
    if (progress_ == ProgressMode::kNone || total <= 1) return;
    const auto now = std::chrono::steady_clock::now();
    if (progress_ == ProgressMode::kAuto) {
        if (done < total && now - last_ < std::chrono::milliseconds(200)) return;
        last_ = now;
        std::cerr << '\r' << program_ << ": frame " << done << "/" << total << std::flush;
        if (done == total) std::cerr << "\r\033[K" << std::flush;
        return;
    }
    // A line a second at most, and the last frame's always: for a log.
    if (done < total && now - last_ < std::chrono::seconds(1)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    char line[160];
    if (done < total) {
        const double left = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
        std::snprintf(line, sizeof line, "frame %zu/%zu (%.0f%%), %.1f s so far, about %.1f s left", done, total,
                      100.0 * static_cast<double>(done) / static_cast<double>(total), elapsed, left);
    } else {
        std::snprintf(line, sizeof line, "frame %zu/%zu (100%%), %.1f s", done, total, elapsed);
    }
    std::cerr << program_ << ": " << line << std::endl;
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
