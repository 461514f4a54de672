#include "sw/timing/timing_quality.h"

#include <algorithm>
#include <cstdio>

namespace cdvp {

double repeat_spread_of(const std::vector<double>& run_means) {
    if (run_means.size() < 2) return 0;
    const auto [lo, hi] = std::minmax_element(run_means.begin(), run_means.end());
    return *lo > 0 ? *hi / *lo - 1 : 0;
}

std::string TimingQuality::describe(uint32_t max_tries) const {
    char text[320];
    const auto frames = static_cast<unsigned long long>(frames_timed);
    std::string out = verdict();
    std::string parts;
    const auto add = [&parts](const std::string& part) { parts += (parts.empty() ? "" : ", ") + part; };
    if (never_clean > 0) {
        std::snprintf(text, sizeof text, "%llu of %llu frames never came clean after %u %s",
                      static_cast<unsigned long long>(never_clean), frames, max_tries, max_tries == 1 ? "try" : "tries");
        add(text);
    }
    if (frames_retimed > 0) {
        std::snprintf(text, sizeof text, "%llu of %llu frames re-timed", static_cast<unsigned long long>(frames_retimed),
                      frames);
        add(text);
    }
    if (frames_slowed > 0) {
        std::snprintf(text, sizeof text, "%llu on a slowed CPU", static_cast<unsigned long long>(frames_slowed));
        add(text);
    }
    if (runs > 1) {
        std::snprintf(text, sizeof text, "repeats %.1f%% apart%s", 100 * repeat_spread,
                      repeat_spread > kMaxRepeatSpread ? " (over 10%)" : "");
        add(text);
    }
    std::snprintf(text, sizeof text, "load %.2f to %.2f", load_start[0], load_end[0]);
    add(text);
    return out + (clean() ? " (" + parts + ")" : ": " + parts);
}

std::string TimingQuality::advice(uint32_t max_tries, bool pinned, uint32_t cpus) const {
    if (clean()) return {};
    std::string out;
    const auto add = [&out](const std::string& part) { out += (out.empty() ? "" : ", ") + part; };
    char text[160];
    // Another task on the CPUs, or a slowed CPU: only a quieter machine helps.
    if (cpus > 0 && load_end[0] >= 0.5 * cpus) {
        std::snprintf(text, sizeof text, "a quieter machine (load %.2f on %u CPU%s)", load_end[0], cpus, cpus == 1 ? "" : "s");
        add(text);
    } else if (frames_slowed > 0) {
        add("a quieter machine (a neighbour or a lowered clock slowed the CPU)");
    }
    // Frames moved or pre-empted, not only slowed: a CPU of its own.
    if (!pinned && frames_disturbed > frames_slowed) add("--pin-cpu N");
    if (never_clean > 0) {
        std::snprintf(text, sizeof text, "--retime-tries %u", std::max(2 * max_tries, 6u));
        add(text);
    }
    if (runs > 1 && repeat_spread > kMaxRepeatSpread) {
        std::snprintf(text, sizeof text, "--repeat %u (the median run counts)", std::max(runs + 2, 5u));
        add(text);
    }
    return out.empty() ? std::string() : "to time it clean: " + out;
}

TimingQuality& TimingQuality::operator+=(const TimingQuality& other) {
    frames_timed += other.frames_timed;
    frames_disturbed += other.frames_disturbed;
    frames_retimed += other.frames_retimed;
    frames_slowed += other.frames_slowed;
    tries += other.tries;
    never_clean += other.never_clean;
    repeat_spread = std::max(repeat_spread, other.repeat_spread);
    runs = std::max(runs, other.runs);
    return *this;
}

}  // namespace cdvp
