// A pool the system will not start all the threads of: the ones started are
// stopped and joined, and the pool says so in one line (ThreadsUnavailable),
// so that a run refuses instead of hanging or aborting. Each case runs in a
// forked child (under a lowered address-space limit, or with the memory for a
// thread's state made to run out), with an alarm, so that a pool that hangs
// fails the test instead of hanging it.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <string>

#include "sw/baselines/broad_phase.h"
#include "sw/baselines/worker_pool.h"

// Memory that runs out on the thread that sets this: the allocation after
// this many more fails (std::bad_alloc); -1: none fails. Not under
// AddressSanitizer, which keeps every form of operator new and delete its own
// (replacing some of them pairs its allocations with our free).
static thread_local long allocations_before_failure = -1;
#if defined(__SANITIZE_ADDRESS__) || defined(CDVP_CODE_UNDER_ASAN)
#define CDVP_OPERATOR_NEW_REPLACED 0
#else
#define CDVP_OPERATOR_NEW_REPLACED 1

void* operator new(std::size_t size) {
    if (allocations_before_failure == 0) {
        allocations_before_failure = -1;
        throw std::bad_alloc();
    }
    if (allocations_before_failure > 0) --allocations_before_failure;
    if (void* block = std::malloc(size == 0 ? 1 : size)) return block;
    throw std::bad_alloc();
}
// The blocks come from malloc above, which GCC cannot see of a replaced operator new.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpragmas"
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
#pragma GCC diagnostic pop
#endif

namespace cdvp {
namespace {

// The process's address space now, in bytes (VmSize), or 0.
rlim_t address_space_now() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
        if (line.rfind("VmSize:", 0) == 0) return static_cast<rlim_t>(std::stoull(line.substr(7))) * 1024;
    }
    return 0;
}

// Runs 'body' in a child, with 64 MiB of address space beyond what it has
// (room for a few threads' stacks, not 256) when 'little_memory', and at most
// 20 s; its exit status, or 128 + the signal that ended it (SIGALRM: it hung).
template <typename Body>
int in_child(Body body, bool little_memory) {
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        alarm(20);
        if (little_memory) {
            const rlim_t now = address_space_now();
            if (now == 0) _exit(90);
            rlimit limit{now + (rlim_t{64} << 20), now + (rlim_t{64} << 20)};
            if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(91);
        }
        _exit(body());
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
template <typename Body>
int in_child_with_little_memory(Body body) {
    return in_child(body, true);
}

// Memory that runs out as a thread's state is made (std::thread allocates it
// before the system starts the thread: a full address space can fail there
// first) is a thread that cannot be made like any other: the started ones
// are stopped and joined, not left waiting on a condition variable the
// failed constructor destroys (which never returns: the run hung).
TEST(WorkerPool, MemoryRunOutMakingAThreadStopsTheStartedOnesAndSaysSo) {
    if (!CDVP_OPERATOR_NEW_REPLACED) GTEST_SKIP() << "AddressSanitizer's operator new cannot be made to fail here";
    const int status = in_child(
        [] {
            try {
                allocations_before_failure = 4;  // the list of threads, then two or three threads' states
                WorkerPool pool(8);
                allocations_before_failure = -1;
                return 10;
            } catch (const ThreadsUnavailable& e) {
                allocations_before_failure = -1;
                const std::string line = e.what();
                if (line.rfind("8 threads asked; the system started ", 0) != 0) return 11;
                if (line.find(" (out of memory); expected fewer") == std::string::npos) return 12;
                if (line.find("started 1 (") != std::string::npos) return 13;  // none was started: nothing tested
            }
            WorkerPool small(2);
            int ran[2] = {0, 0};
            small.run([&](unsigned t) { ran[t] = 1; });
            return ran[0] + ran[1] == 2 ? 0 : 14;
        },
        false);
    EXPECT_EQ(status, 0) << "10: all started; 11, 12: the line; 13: none started; 14: the small pool; 128+14: it hung; "
                            "128+6: it aborted";
}

TEST(WorkerPool, AThreadTheSystemRefusesStopsTheStartedOnesAndSaysSo) {
    const int status = in_child_with_little_memory([] {
        try {
            WorkerPool pool(256);
            return 10;  // the limit let all of them start: nothing tested
        } catch (const ThreadsUnavailable& e) {
            const std::string line = e.what();
            if (line.rfind("256 threads asked; the system started ", 0) != 0) return 11;
            if (line.find("expected fewer") == std::string::npos || line.find('\n') != std::string::npos) return 12;
        }
        // The process goes on: a pool of the threads the system has works.
        WorkerPool small(2);
        int ran[2] = {0, 0};
        small.run([&](unsigned t) { ran[t] = 1; });
        return ran[0] + ran[1] == 2 ? 0 : 13;
    });
    EXPECT_EQ(status, 0) << "10: all started; 11, 12: the line; 13: the small pool; 128+14: it hung; 128+6: it aborted";
}

// The same through a multi-threaded baseline: it is not made, and the broad
// phases the system has threads for still find their pairs.
TEST(WorkerPool, AMultiThreadedBaselineWithoutItsThreadsIsNotMade) {
    const int status = in_child_with_little_memory([] {
        for (const char* name : {"sap_mt", "prune_mt", "hgrid_mt"}) {
            try {
                make_broad_phase(name, BaselineOptions{256});
                return 10;
            } catch (const ThreadsUnavailable&) {
            }
        }
        auto phase = make_broad_phase("sap_mt", BaselineOptions{2});
        std::vector<FloatBox> boxes(3, FloatBox{{0, 0, 0}, {1, 1, 1}});
        PairList found;
        phase->find_pairs(boxes, found);
        return found.size() == 3 ? 0 : 13;
    });
    EXPECT_EQ(status, 0) << "10: all started; 13: the pairs; 128+14: it hung; 128+6: it aborted";
}

}  // namespace
}  // namespace cdvp
