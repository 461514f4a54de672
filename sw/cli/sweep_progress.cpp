#include "sw/cli/sweep_progress.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace cdvp {

void SweepProgress::started(std::size_t total, std::size_t done) {
    total_ = total;
    done_ = done_before_ = done;
    start_ = std::chrono::steady_clock::now();
    draw();
}

void SweepProgress::point_done() {
    ++done_;
    draw();
}

void SweepProgress::draw() {
    if (!enabled_) return;
    constexpr std::size_t kWidth = 30;
    const std::size_t filled = total_ == 0 ? kWidth : kWidth * done_ / total_;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::size_t run_now = done_ - done_before_;
    char rate[96] = "";
    if (run_now > 0 && seconds > 0) {
        const double per_second = static_cast<double>(run_now) / seconds;
        const long left = static_cast<long>(static_cast<double>(total_ - done_) / per_second + 0.5);
        std::snprintf(rate, sizeof rate, "  %.2f points/s  ETA %ld:%02ld:%02ld", per_second, left / 3600, left / 60 % 60,
                      left % 60);
    }
    std::cerr << "\rcdvp sweep [" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] " << done_
              << "/" << total_ << " points" << rate << "\033[K" << std::flush;
    drawn_ = true;
}

void SweepProgress::points_ended() {
    if (drawn_) std::cerr << "\r\033[K" << std::flush;
    drawn_ = false;
}

}  // namespace cdvp
