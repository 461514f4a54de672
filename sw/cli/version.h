// The version `cdvp --version` prints and every report records.
#pragma once

namespace cdvp {

constexpr const char* kCdvpVersion = "0.1.0";

}  // namespace cdvp
