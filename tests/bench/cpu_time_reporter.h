// Google Benchmark's console table, keeping each run's CPU time per
// iteration for a summary the benchmark prints after it (CPU time, not wall:
// the machine may be shared).
#pragma once

#include <unistd.h>

#include <benchmark/benchmark.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace cdvp::bench {

class CpuTimeReporter : public benchmark::ConsoleReporter {
public:
    CpuTimeReporter() : ConsoleReporter(isatty(1) ? OO_ColorTabular : OO_Tabular) {}
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.run_type == Run::RT_Iteration && run.iterations > 0 && !medians_.count(run.run_name.str())) {
                cpu_s_[run.run_name.str()] = run.cpu_accumulated_time / static_cast<double>(run.iterations);
            } else if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
                // Over repetitions the median, also when only aggregates are reported.
                cpu_s_[run.run_name.str()] = run.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(run.time_unit);
                medians_.insert(run.run_name.str());
            }
        }
    }
    // A benchmark's CPU seconds per iteration (0 if it did not run).
    double cpu_s(const std::string& name) const {
        auto it = cpu_s_.find(name);
        return it == cpu_s_.end() ? 0.0 : it->second;
    }
    double cpu_ms(const std::string& name) const { return 1e3 * cpu_s(name); }
    double cpu_us(const std::string& name) const { return 1e6 * cpu_s(name); }

private:
    std::map<std::string, double> cpu_s_;
    std::set<std::string> medians_;
};

}  // namespace cdvp::bench
