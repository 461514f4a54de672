#include "sw/timing/thread_timer.h"

#include <sched.h>
#include <sys/resource.h>
#include <time.h>

#include <cerrno>
#include <cstring>

namespace cdvp {

namespace {

int64_t read_clock(clockid_t clock) {
    timespec now{};
    clock_gettime(clock, &now);
    return static_cast<int64_t>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}

long involuntary_switches() {
    rusage usage{};
    getrusage(RUSAGE_THREAD, &usage);
    return usage.ru_nivcsw;
}

}  // namespace

int64_t thread_cpu_ns() { return read_clock(CLOCK_THREAD_CPUTIME_ID); }

// The rusage and CPU reads sit outside the clocks' interval, so that their
// system calls are not part of the time.
CallTimer::Mark CallTimer::mark() {
    Mark m;
    m.involuntary = involuntary_switches();
    m.cpu = sched_getcpu();
    m.wall_ns = read_clock(CLOCK_MONOTONIC);
    m.cpu_ns = read_clock(CLOCK_THREAD_CPUTIME_ID);
    m.process_cpu_ns = read_clock(CLOCK_PROCESS_CPUTIME_ID);
    return m;
}

CallTiming CallTimer::since(const Mark& start) {
    const int64_t cpu_ns = read_clock(CLOCK_THREAD_CPUTIME_ID);
    const int64_t process_cpu_ns = read_clock(CLOCK_PROCESS_CPUTIME_ID);
    const int64_t wall_ns = read_clock(CLOCK_MONOTONIC);
    const int cpu = sched_getcpu();
    const long involuntary = involuntary_switches();
    CallTiming t;
    t.cpu_ns = static_cast<double>(cpu_ns - start.cpu_ns);
    t.wall_ns = static_cast<double>(wall_ns - start.wall_ns);
    t.process_cpu_ns = static_cast<double>(process_cpu_ns - start.process_cpu_ns);
    t.involuntary_switches = involuntary > start.involuntary ? static_cast<uint64_t>(involuntary - start.involuntary) : 0;
    t.migrated = cpu != start.cpu;
    return t;
}

std::optional<std::string> pin_thread_to_cpu(uint32_t cpu) {
    if (std::optional<std::string> refused = unpinnable_cpu(cpu)) return refused;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    if (sched_setaffinity(0, sizeof one, &one) != 0) return "cannot pin to CPU " + std::to_string(cpu) + ": " + std::strerror(errno);
    return std::nullopt;
}

std::optional<std::string> unpinnable_cpu(uint32_t cpu) {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return std::string("cannot read this process's CPUs: ") + std::strerror(errno);
    if (cpu >= CPU_SETSIZE || !CPU_ISSET(cpu, &allowed)) {
        std::string list;
        for (int k = 0; k < CPU_SETSIZE; ++k) {
            if (CPU_ISSET(k, &allowed)) list += (list.empty() ? "" : ",") + std::to_string(k);
        }
        return "CPU " + std::to_string(cpu) + " is not one this process may run on (" + list + ")";
    }
    return std::nullopt;
}

}  // namespace cdvp
