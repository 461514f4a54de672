// The machine a run or a calibration is timed on, and how busy it is: what
// a software time cannot be read without.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace cdvp {

struct MachineInfo {
    std::string cpu_model = "unknown";  // /proc/cpuinfo's first "model name"
    double cpu_mhz = 0;                 // its "cpu MHz" when read (0: not known)
    uint32_t cores_online = 0;          // processors the system runs
    uint32_t cores_allowed = 0;         // of those, the ones this process may run on (taskset)
    std::string kernel = "unknown";     // uname's release
};

MachineInfo read_machine_info();

// The 1, 5 and 15-minute load averages (zeros when unknown).
std::array<double, 3> load_average();

}  // namespace cdvp
