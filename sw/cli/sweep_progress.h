// The progress bar of `cdvp sweep` on a terminal: points done of the total,
// the rate and the time left, redrawn in place on stderr.
#pragma once

#include <chrono>
#include <cstddef>

namespace cdvp {

class SweepProgress {
public:
    // 'done' points of 'total' were done before this run (resumed).
    SweepProgress(std::size_t total, std::size_t done, bool enabled);
    void point_done();
    // Clears the bar.
    void finish();

private:
    void draw();

    std::size_t total_, done_, done_before_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace cdvp
