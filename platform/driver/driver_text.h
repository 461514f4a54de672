// How the driver's messages write addresses, sizes and times.
#pragma once

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>

#include "platform/driver/host_port.h"

namespace cdvp {

inline std::string hex(uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%" PRIx64, value);
    return text;
}

inline std::string mebibytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g MiB", static_cast<double>(bytes) / (1 << 20));
    return text;
}

inline std::string microseconds(SimTime t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g us", ns_from_fs(t) * 1e-3);
    return text;
}

}  // namespace cdvp
