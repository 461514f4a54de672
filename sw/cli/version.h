// The version `cdvp --version` prints and every report records: CMake's project version.
#pragma once

namespace cdvp {

constexpr const char* kCdvpVersion = CDVP_VERSION;

}  // namespace cdvp
