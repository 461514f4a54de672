// What every cdvp command returns: its exit status, and the one line on
// stderr that says why when it is not 0.
#pragma once

#include <functional>
#include <string>

namespace cdvp {

// Exit statuses of cdvp (README: exit status; docs/numerics.md).
constexpr int kExitDone = 0;
constexpr int kExitInternal = 1;     // a cdvp bug
constexpr int kExitBadInput = 2;     // a bad trace, flag, preset or output path
constexpr int kExitDeviceFault = 3;  // the simulated system faulted (bus, DMA, driver timeout, board error)
constexpr int kExitSystem = 4;       // the operating system failed a write or a resource (disk full, I/O error)

// Runs a command's body and maps what escapes it to the exit status: an
// InputError is bad input (kExitBadInput, "PROGRAM: message"), a SystemError
// the system's failure (kExitSystem, "PROGRAM: message" with the system's
// own error text), any other exception a bug (kExitInternal, "PROGRAM:
// internal error (a cdvp bug): message"); each one line on stderr.
int exit_status_of(const std::string& program, const std::function<int()>& body);

struct OutputFailure;
// Prints a failed commit's one line under 'program'; its exit status
// (kExitSystem for a full disk or an I/O error, else kExitBadInput).
int commit_failed(const std::string& program, const OutputFailure& failure);

// Prints 'text' (help, version) on standard output: kExitDone, or
// kExitSystem or kExitBadInput with one line on stderr when it cannot be written.
int print_to_stdout(const std::string& program, const std::string& text);

}  // namespace cdvp
