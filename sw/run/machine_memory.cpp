#include "sw/run/machine_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "sw/output/child_process.h"

namespace cdvp {

namespace {

// A cgroup without a limit reads "max" (v2) or a value near 2^63 (v1).
constexpr uint64_t kNoLimitAbove = uint64_t{1} << 62;

// The limit in `file`, 0 when there is none or no such file.
uint64_t limit_in(const std::string& file) {
    std::ifstream in(file);
    std::string text;
    if (!(in >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return 0;
    try {
        const uint64_t value = std::stoull(text);
        return value >= kNoLimitAbove ? 0 : value;
    } catch (const std::exception&) {
        return 0;
    }
}

// The least limit along `path` and its ancestors, in files named `name`
// under `base`.
uint64_t least_along(const std::string& base, std::string path, const char* name) {
    uint64_t least = 0;
    for (;;) {
        const uint64_t limit = limit_in(base + (path == "/" ? "" : path) + "/" + name);
        if (limit != 0) least = least == 0 ? limit : std::min(least, limit);
        if (path.empty() || path == "/") return least;
        const std::size_t slash = path.find_last_of('/');
        path = slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
    }
}

uint64_t lesser(uint64_t a, uint64_t b) { return a == 0 ? b : b == 0 ? a : std::min(a, b); }

}  // namespace

uint64_t cgroup_memory_limit(const std::string& proc_self_cgroup, const std::string& root) {
    std::istringstream lines(proc_self_cgroup);
    uint64_t least = 0;
    for (std::string line; std::getline(lines, line);) {
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        const std::string path = line.substr(second + 1);
        if (controllers.empty()) {
            least = lesser(least, least_along(root, path, "memory.max"));  // v2: one unified hierarchy
            continue;
        }
        std::istringstream names(controllers);
        for (std::string name; std::getline(names, name, ',');) {
            if (name == "memory") least = lesser(least, least_along(root + "/memory", path, "memory.limit_in_bytes"));
        }
    }
    return least;
}

MachineMemory machine_memory() {
    // The machine's memory and the cgroup's limit, read once a process (a
    // sweep asks before each of its points).
    static const MachineMemory machine = [] {
        MachineMemory read;
        const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
        if (pages > 0 && page > 0) read.physical = static_cast<uint64_t>(pages) * static_cast<uint64_t>(page);
        std::ifstream in("/proc/self/cgroup");
        std::stringstream text;
        text << in.rdbuf();
        read.cgroup = cgroup_memory_limit(text.str(), "/sys/fs/cgroup");
        return read;
    }();
    MachineMemory memory;
    memory.physical = machine.physical;
    memory.cgroup = machine.cgroup;
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) memory.address_space = limit.rlim_cur;
    if (const char* share = std::getenv(kMemoryShareVariable); share != nullptr) {
        const std::string text = share;
        if (!text.empty() && text.size() <= 4 && text.find_first_not_of("0123456789") == std::string::npos) {
            memory.sharing = std::clamp<uint64_t>(std::stoull(text), 1, 1024);
        }
    }
    return memory;
}

uint64_t MachineMemory::least() const { return lesser(lesser(physical, cgroup), address_space); }

std::string MachineMemory::describe_least() const {
    const uint64_t value = least();
    if (value != 0 && value == address_space) return "RLIMIT_AS of " + size_text(value);
    if (value != 0 && value == cgroup) return "the cgroup's memory limit of " + size_text(value);
    return "this machine's " + size_text(value) + " of memory";
}

std::string size_text(uint64_t bytes) {
    const double mib = static_cast<double>(bytes) / (1 << 20);
    char text[40];
    std::snprintf(text, sizeof text, mib >= 10 ? "%.0f MiB" : "%.1f MiB", mib);
    return text;
}

}  // namespace cdvp
