#include "sw/cli/exit_status.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <new>

#include "models/common/user_text.h"
#include "sw/output/output_set.h"
#include "sw/output/output_target.h"

namespace cdvp {

CommandFailure failure_of_current_exception(const std::string& program) {
    const Failure failure = failure_of_current_exception();
    return {failure.status, program + ": " + failure.message};
}

int exit_status_of(const std::string& program, const std::function<int()>& body) {
    try {
        return body();
    } catch (const std::exception&) {
        const CommandFailure failure = failure_of_current_exception(program);
        std::cerr << failure.line << '\n';
        return failure.status;
    }
}

int commit_failed(const std::string& program, const OutputFailure& failure) {
    std::cerr << program << ": " << printable(failure.message) << '\n';
    return failure.system() ? kExitSystem : kExitBadInput;
}

int print_to_stdout(const std::string& program, const std::string& text) {
    if (standard_descriptor_was_closed(STDOUT_FILENO)) {
        std::cerr << program << ": standard output: closed when cdvp started; expected it open\n";
        return kExitBadInput;
    }
    errno = 0;
    std::cout << text << std::flush;
    if (std::cout) return kExitDone;
    const int error = errno != 0 ? errno : EIO;
    std::cerr << program << ": standard output: cannot write: " << std::strerror(error) << '\n';
    return is_system_failure(error) ? kExitSystem : kExitBadInput;
}

}  // namespace cdvp
