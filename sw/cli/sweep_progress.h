// The progress bar of `cdvp sweep` on a terminal: points done of the total,
// the rate and the time left, redrawn in place on stderr.
#pragma once

#include <chrono>
#include <cstddef>

#include "sw/study/sweep.h"

namespace cdvp {

class SweepProgress : public SweepObserver {
public:
    explicit SweepProgress(bool enabled) : enabled_(enabled) {}
    // 'done' points of 'total' were done before this run (resumed).
    void started(std::size_t total, std::size_t done) override;
    void point_done() override;
    // Clears the bar.
    void points_ended() override;

private:
    void draw();

    std::size_t total_ = 0, done_ = 0, done_before_ = 0;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace cdvp
