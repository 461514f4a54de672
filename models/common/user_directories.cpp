#include "models/common/user_directories.h"

#include <cstdlib>

namespace cdvp {

std::string user_base_directory(const char* variable, const char* home_fallback) {
    const char* value = std::getenv(variable);
    if (value != nullptr && value[0] == '/') return value;
    const char* home = std::getenv("HOME");
    if (home != nullptr && home[0] == '/') return std::string(home) + "/" + home_fallback;
    return {};
}

}  // namespace cdvp
