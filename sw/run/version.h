// The version `cdvp --version` prints, every report records and a sweep's
// manifest holds: CMake's project version.
#pragma once

namespace cdvp {

extern const char* const kCdvpVersion;

}  // namespace cdvp
