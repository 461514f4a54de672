// What every cdvp command returns: its exit status, and the one line on
// stderr that says why when it is not 0.
#pragma once

#include <functional>
#include <string>

#include "sw/run/exit_codes.h"

namespace cdvp {

// Runs a command's body and maps what escapes it to the exit status: an
// InputError is bad input (kExitBadInput, "PROGRAM: message"), a SystemError
// the system's failure (kExitSystem, "PROGRAM: message" with the system's
// own error text), any other exception a bug (kExitInternal, "PROGRAM:
// internal error (a cdvp bug): message"); each one line on stderr.
int exit_status_of(const std::string& program, const std::function<int()>& body);

// The exception being handled (call it inside a catch) as exit_status_of
// maps it: the exit status and the one line, without its newline. An
// exception not derived from std::exception is rethrown.
struct CommandFailure {
    int status;
    std::string line;
};
CommandFailure failure_of_current_exception(const std::string& program);

struct OutputFailure;
// Prints a failed commit's one line under 'program'; its exit status
// (kExitSystem for a full disk or an I/O error, else kExitBadInput).
int commit_failed(const std::string& program, const OutputFailure& failure);

// Prints 'text' (help, version) on standard output: kExitDone, or
// kExitSystem or kExitBadInput with one line on stderr when it cannot be written.
int print_to_stdout(const std::string& program, const std::string& text);

}  // namespace cdvp
