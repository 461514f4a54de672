#include "models/common/input_path.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "models/common/user_text.h"

namespace cdvp {

std::string errno_reason(int error) {
    if (error == 0) return "not a regular file";
    const char* name = strerrorname_np(error);
    return std::string(std::strerror(error)) + (name != nullptr ? " (" + std::string(name) + ")" : "");
}

InputPresence input_presence(const std::string& path) {
    struct stat status {};
    if (stat(path.c_str(), &status) == 0) return {InputPresence::Kind::kPresent, {}};
    if (errno == ENOENT) return {InputPresence::Kind::kAbsent, {}};
    return {InputPresence::Kind::kUnreadable, errno_reason(errno)};
}

void refuse_input(const std::string& shown, int error, const std::string& expected) {
    throw InputError(shown + ": cannot open: " + errno_reason(error) + (expected.empty() ? "" : "; " + expected));
}

void require_regular_file(const std::string& path, const std::string& shown) {
    const std::string named = shown.empty() ? path : shown;
    struct stat status {};
    if (stat(path.c_str(), &status) != 0) refuse_input(named, errno);
    if (S_ISDIR(status.st_mode)) refuse_input(named, EISDIR);
    if (!S_ISREG(status.st_mode)) refuse_input(named, 0);
}

}  // namespace cdvp
