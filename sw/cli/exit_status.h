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

// Runs a command's body and maps what escapes it to the exit status: an
// InputError is bad input (kExitBadInput, "PROGRAM: message"), any other
// exception an internal failure (kExitInternal, "PROGRAM: FAILURE: message");
// each one line on stderr.
int exit_status_of(const std::string& program, const char* failure, const std::function<int()>& body);

// Prints 'text' (help, version) on standard output: kExitDone, or
// kExitBadInput with one line on stderr when it cannot be written.
int print_to_stdout(const std::string& program, const std::string& text);

}  // namespace cdvp
