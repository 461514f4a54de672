// One configuration run on a scene or trace, from a program of one's own: the
// C++ entry point of the study library (docs/library.md). The run is `cdvp
// run` in a child process, so that a program may run any number of them
// (SystemC elaborates a design once per process), a refused or faulting run
// cannot take the caller down, and the results are the command's byte for
// byte; its report is read back typed.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sw/study/report_summary.h"

namespace cdvp {

struct RunRequest {
    // Options of cdvp run, one word each: {"--board", "adm-xrc-ii", "--scene",
    // "spheres", "--objects", "500", "-c", "bus.interrupt_ns=5000"}. --report,
    // --pairs-out and -q are the study's own.
    std::vector<std::string> options;
    bool pairs = false;        // also read back the pairs (RunResult::pairs_csv)
    std::string cdvp_binary;   // empty: find_cdvp()
};

struct RunResult {
    nlohmann::json report;     // the whole report as the run wrote it (README: file formats)
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

// Throws RunFailed, or InputError when the options are the study's own.
RunResult run_configuration(const RunRequest& request);

// The cdvp the study runs: $CDVP_BINARY when set, else a cdvp beside the
// running executable, else the first on PATH. Throws InputError when there is none.
std::string find_cdvp();

}  // namespace cdvp
