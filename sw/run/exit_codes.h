// What a cdvp run's exit status means: returned by every command, and read
// back by the study when it runs `cdvp run` as a child (docs/cli.md: exit status).
#pragma once

#include <string>

namespace cdvp {

constexpr int kExitDone = 0;
constexpr int kExitInternal = 1;     // a cdvp bug
constexpr int kExitBadInput = 2;     // a bad trace, flag, preset or output path
constexpr int kExitDeviceFault = 3;  // the simulated system faulted (bus, DMA, driver timeout, board error)
constexpr int kExitSystem = 4;       // the operating system failed a write or a resource (disk full, I/O error)

// The exception being handled (call it inside a catch) as an exit status and
// its one line, without a program's name: an InputError is bad input, a
// SystemError the system's failure, anything else a bug ("internal error (a
// cdvp bug): ..."). An exception not derived from std::exception is rethrown.
struct Failure {
    int status;
    std::string message;
};
Failure failure_of_current_exception();

}  // namespace cdvp
