// This machine's CPU package energy, where the kernel exposes it: Intel's
// (and AMD's) RAPL counters under /sys/class/powercap (intel-rapl:N, the
// package domains; energy_uj counts up and wraps at max_energy_range_uj).
// Where there are none, or they cannot be read (they are root's alone on
// kernels since 5.10), a run states the host's package power instead, and
// its report says which (docs/energy.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cdvp {

class RaplMeter {
public:
    // root: the powercap directory (a test's stand-in; the kernel's by default).
    explicit RaplMeter(std::string root = "/sys/class/powercap");
    // Whether any package counter can be read.
    bool available() const { return !packages_.empty(); }
    // The packages' energy counters summed, in joules, as read now (0 without any).
    double joules() const;
    // The energy between two readings of joules(), each counter's wrap undone.
    double joules_since(double start) const;

private:
    struct Package {
        std::string energy_path;
        double range_j = 0;  // where the counter wraps
    };
    std::vector<Package> packages_;
};

}  // namespace cdvp
