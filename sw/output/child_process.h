// Child processes as every layer that starts one needs them: a child's
// output captured in memory, a child that dies with its parent, programs
// found on PATH. The run layer converts waveforms with vcd2fst; the study
// library runs cdvp and gnuplot.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cdvp {

// A child's stdout or stderr kept in an anonymous in-memory file (memfd): no
// name in any directory, so nothing is left behind however the process ends,
// and no $TMPDIR is needed.
class CapturedOutput {
public:
    explicit CapturedOutput(const char* name);
    ~CapturedOutput();
    CapturedOutput(const CapturedOutput&) = delete;
    CapturedOutput& operator=(const CapturedOutput&) = delete;
    int fd() const { return fd_; }
    // What was written, from the start, at most 'max_bytes'.
    std::string text(std::size_t max_bytes = std::size_t{1} << 20) const;
    // Empties it for the next child.
    void clear();

private:
    int fd_ = -1;
};

// The environment variable through which a parent running J children at once
// tells each that its default memory budget is a J-th of the machine's.
constexpr const char* kMemoryShareVariable = "CDVP_MEMORY_SHARE";

// The running cdvp executable, for its child runs.
std::string self_path();

// Where a child's standard streams go and which descriptors it inherits.
struct ChildStreams {
    int in = -1;   // standard input; -1: /dev/null
    int out = -1;  // standard output; -1: this process's
    int err = -1;  // standard error; -1: this process's
    std::vector<int> inherited;  // descriptors the child keeps open (its /proc/self/fd/N paths)
};

// The first executable named 'name' on PATH (a name with a '/' is taken as
// a path), or nothing when there is none.
std::optional<std::string> find_program(const std::string& name);

// Starts args[0] (an absolute path, or looked up in PATH) with 'streams'; the
// child gets SIGTERM should this process die first (even by SIGKILL), so no
// point outlives its sweep. Returns its pid; throws when it cannot start.
pid_t start_child(const std::vector<std::string>& args, const ChildStreams& streams);
// Waits for that child (restarting after a signal handler ran); its wait status.
int wait_child(pid_t pid);
// start_child, then wait_child.
int run_child(const std::vector<std::string>& args, const ChildStreams& streams);

}  // namespace cdvp
