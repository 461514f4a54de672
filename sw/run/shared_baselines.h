// A run's software timing shared through a directory (--software-timings,
// which cdvp sweep gives every point): a run whose workload has a timing there
// takes its figures from it and times nothing; a run whose workload has none
// times its baselines and adds its timing for the others (sw/study/
// software_timing.h). So every point of one workload divides by one figure.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/output/created_directories.h"
#include "sw/run/frame_source.h"
#include "sw/run/host_factor.h"
#include "sw/run/run_report.h"
#include "sw/run/software_timing.h"

namespace cdvp {

class SettingValues;

// What the software's work depends on: the scene and its settings or the
// trace's frames, the baselines, their repeats, warm-up and re-timing, and
// what the native times are taken on (this cdvp, this CPU, the host profile
// its factors rest on). The source is read through for a trace and rewound.
nlohmann::json software_workload(const std::string& scene, FrameSource& source, const SettingValues& values,
                                 const std::vector<std::string>& baselines, const HostTiming& host);

class SharedBaselines {
public:
    // Makes DIR as mkdir -p (removed again unless a timing is added to it),
    // then reads its timing of `workload` if there is one, checked against
    // the run: `baselines` with `runs` runs of `frames` frames each. Throws
    // InputError naming `label` and DIR when DIR is no directory and cannot
    // be made one, or naming the file for a timing that does not fit.
    SharedBaselines(std::string dir, const std::string& label, nlohmann::json workload,
                    const std::vector<std::string>& baselines, uint32_t runs, std::size_t frames);

    // A timing was there: the run times nothing and reports this one.
    bool loaded() const { return timing_.has_value(); }
    // The first run's frame `index`, as the run reports it (host factors applied).
    std::map<std::string, BaselineTime> frame(std::size_t index, const HostTiming& host) const;
    // The loaded timing's later runs and quality into `totals` (its first run came with the frames).
    void complete(RunTotals& totals) const;
    // After the run timed its own: adds it to DIR (which stays, made or
    // not); when another run added one first, `totals` takes that one
    // instead. Throws SystemError or InputError when DIR cannot be written.
    void publish(RunTotals& totals, uint32_t retime_tries);
    // What the rows name: KEY@SHA.
    const std::string& id() const { return id_; }

private:
    void take(RunTotals& totals, bool with_first_run) const;

    CreatedDirectories made_;  // DIR and its parents, when this run made them
    std::string dir_;
    nlohmann::json workload_;
    std::string key_, id_;
    std::size_t max_bytes_;  // the largest timing file of this run's shape (software_timing_max_bytes)
    std::optional<SoftwareTiming> timing_;
};

}  // namespace cdvp
