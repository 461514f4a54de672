// The build that is running: recorded in every report and host profile, since
// a software baseline's time depends on the compiler and flags as much as on
// the machine.
#pragma once

#include <string>

namespace cdvp {

struct BuildInfo {
    std::string version;     // CMake's project version
    std::string git_commit;  // at configure time; "unknown" outside a git checkout
    std::string compiler;    // "GNU 12.2.0"
    std::string build_type;  // "Release"
    std::string flags;       // the C++ flags of that build type and the project's compile options
};

const BuildInfo& build_info();

}  // namespace cdvp
