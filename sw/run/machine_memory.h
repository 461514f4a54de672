// How much memory this process may have: the machine's physical memory, and
// the lower limits a container or a shell may set (a cgroup's memory limit,
// RLIMIT_AS). The default memory budget of a run is a share of the least.
#pragma once

#include <cstdint>
#include <string>

namespace cdvp {

struct MachineMemory {
    uint64_t physical = 0;       // bytes of RAM
    uint64_t cgroup = 0;         // the cgroup's memory limit (v2 memory.max, v1 memory.limit_in_bytes); 0: none
    uint64_t address_space = 0;  // RLIMIT_AS (soft); 0: unlimited
    // Runs at once that share it: a sweep's --jobs J, told to its points by
    // CDVP_MEMORY_SHARE=J, so that J points' default budgets fit together.
    uint64_t sharing = 1;

    // The least of the limits that are set, and what it is ("this machine's
    // 23.5 GiB of memory", "the cgroup's memory limit of 2.0 GiB", "RLIMIT_AS
    // of 1.0 GiB").
    uint64_t least() const;
    std::string describe_least() const;
};

// This process's: physical memory from sysconf, the cgroup's limit from
// /proc/self/cgroup and the cgroup file systems under /sys/fs/cgroup (a
// limit of an enclosing cgroup counts too), RLIMIT_AS from getrlimit, and
// the runs sharing it from CDVP_MEMORY_SHARE (1 to 1024; else 1).
MachineMemory machine_memory();

// The least memory limit of the cgroup at `cgroup_path` and its ancestors,
// from the cgroup file system mounted at `root` (v2: ROOT/PATH/memory.max, v1:
// ROOT/memory/PATH/memory.limit_in_bytes); 0: none. `proc_self_cgroup` is
// /proc/self/cgroup's text. Separate for tests.
uint64_t cgroup_memory_limit(const std::string& proc_self_cgroup, const std::string& root);

// "23.5 GiB", "512 MiB": a size as messages give it.
std::string size_text(uint64_t bytes);

}  // namespace cdvp
