#include "sw/run/machine_info.h"

#include <sched.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

namespace cdvp {

namespace {

// The value of "key : value" on a line of /proc/cpuinfo that starts with key.
bool cpuinfo_value(const std::string& line, const std::string& key, std::string& value) {
    if (line.compare(0, key.size(), key) != 0) return false;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) return false;
    const std::size_t start = line.find_first_not_of(" \t", colon + 1);
    value = start == std::string::npos ? "" : line.substr(start);
    return true;
}

}  // namespace

MachineInfo read_machine_info() {
    MachineInfo info;
    std::ifstream cpuinfo("/proc/cpuinfo");
    bool model = false, mhz = false;
    for (std::string line, value; std::getline(cpuinfo, line) && !(model && mhz);) {
        if (!model && cpuinfo_value(line, "model name", value)) {
            info.cpu_model = value;
            model = true;
        } else if (!mhz && cpuinfo_value(line, "cpu MHz", value)) {
            info.cpu_mhz = std::strtod(value.c_str(), nullptr);
            mhz = true;
        }
    }
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    info.cores_online = online > 0 ? static_cast<uint32_t>(online) : 0;
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) info.cores_allowed = static_cast<uint32_t>(CPU_COUNT(&allowed));
    utsname names{};
    if (uname(&names) == 0) info.kernel = names.release;
    return info;
}

std::array<double, 3> load_average() {
    // The kernel updates its load averages every 5 s; a sweep asks twice a
    // point, so a reading less than a second old is given again.
    static std::array<double, 3> loads{};
    static std::chrono::steady_clock::time_point read_at{};
    static bool read = false;
    const auto now = std::chrono::steady_clock::now();
    if (read && now - read_at < std::chrono::seconds(1)) return loads;
    double values[3];
    loads = getloadavg(values, 3) == 3 ? std::array<double, 3>{values[0], values[1], values[2]} : std::array<double, 3>{};
    read_at = now;
    read = true;
    return loads;
}

}  // namespace cdvp
