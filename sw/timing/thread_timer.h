// Times one call on the calling thread by what the call itself cost: its
// CPU time (CLOCK_THREAD_CPUTIME_ID), which leaves out whatever time the
// thread spent waiting while other work had its CPU, with the wall time
// beside it; and whether anything disturbed the call: an involuntary context
// switch (getrusage RUSAGE_THREAD) or a move to another CPU (sched_getcpu
// before and after). A disturbed call's CPU time still carries the caches
// another task cooled, so callers time it again (docs/timing.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace cdvp {

struct CallTiming {
    double cpu_ns = 0;   // the estimator
    double wall_ns = 0;  // beside it: what an idle machine's clock on the wall would say
    double process_cpu_ns = 0;  // every thread of the process: a multi-threaded call's threads together
    uint64_t involuntary_switches = 0;
    bool migrated = false;  // ran on another CPU at the end than at the start

    bool disturbed() const { return involuntary_switches > 0 || migrated; }
};

class CallTimer {
public:
    template <class Call>
    static CallTiming time(Call&& call) {
        const Mark start = mark();
        std::forward<Call>(call)();
        return since(start);
    }

private:
    struct Mark {
        long involuntary = 0;
        int cpu = -1;
        int64_t wall_ns = 0;
        int64_t cpu_ns = 0;
        int64_t process_cpu_ns = 0;
    };
    static Mark mark();
    static CallTiming since(const Mark& start);
};

// The calling thread's CPU time so far, in ns: for the stages inside a call
// CallTimer times as a whole.
int64_t thread_cpu_ns();

// Pins the calling thread to one CPU (run.pin_cpu); the reason it could not
// (no such CPU, not in the process's allowed set), or nothing.
std::optional<std::string> pin_thread_to_cpu(uint32_t cpu);
// Why this process could not be pinned to 'cpu' (not in its allowed set),
// or nothing: pin_thread_to_cpu's check, without pinning.
std::optional<std::string> unpinnable_cpu(uint32_t cpu);

}  // namespace cdvp
