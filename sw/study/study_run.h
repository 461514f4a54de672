// One configuration run on a scene or trace, from a program of one's own: the
// C++ entry point of the study library (docs/library.md). A run on the
// SystemC platform is `cdvp run` in a child process, so that a program may
// run any number of them (SystemC elaborates a design once per process) and
// a faulting run cannot take the caller down; a run at the analytic level may
// run in the caller's process (RunRequest::in_process). Either way the
// results are the command's byte for byte; its report is read back typed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/run/report_summary.h"
#include "sw/run/run_spec.h"

namespace cdvp {

class RunObserver;

struct RunRequest {
    // The run (sw/run/run_spec.h): its settings, frames, baselines, faults.
    // Its outputs are the study's own: the report comes back as a RunResult.
    RunSpec spec;
    bool pairs = false;        // also read back the pairs (RunResult::pairs_csv)
    std::string cdvp_binary;   // empty: find_cdvp()
    // A run that elaborates no SystemC kernel (the analytic level) runs in
    // this process; any other in a child.
    bool in_process = false;
    // With in_process: a run that goes to a child is first checked in this
    // process as far as it can be without a kernel (RunContext::check_first),
    // so that its refusals name settings in the spec's words.
    bool check_in_process = false;
    // Told of a run in this process frame by frame (none: nothing is told);
    // an exception it throws stops the run, nothing written.
    RunObserver* observer = nullptr;
};

struct RunResult {
    nlohmann::json report;     // the whole report as the run wrote it (docs/formats.md)
    ReportSummary summary;     // its summary, typed
    std::string pairs_csv;     // with RunRequest::pairs: the pairs CSV of every frame
};

// A run that did not complete: the exit status of cdvp run (2 bad input, 3
// the simulated system faulted, 4 the operating system failed, 1 a cdvp bug)
// and its one-line message ("cdvp run: ..."), as the command prints them.
class RunFailed : public std::runtime_error {
public:
    RunFailed(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
    int status() const { return status_; }

private:
    int status_;
};

// Throws RunFailed, or InputError when the spec names outputs (they are the study's own).
RunResult run_configuration(const RunRequest& request);

// The cdvp the study runs: $CDVP_BINARY when set, else a cdvp beside the
// running executable, else the first on PATH. Throws InputError when there is none.
std::string find_cdvp();

}  // namespace cdvp
