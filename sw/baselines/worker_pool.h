// A fixed set of threads that run one job together and wait for the next:
// kept for a baseline's lifetime, so a frame pays a wake-up, not a thread's
// creation (tens of microseconds, as much as a small frame's whole sweep).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "models/common/user_text.h"

namespace cdvp {

// The system would not start all the threads a pool was asked for (a limit
// on processes or address space): what() is one line, "1024 threads asked;
// the system started 57 (Resource temporarily unavailable); expected fewer",
// for the caller to prefix with the setting that asked (--threads).
class ThreadsUnavailable : public SystemError {
public:
    using SystemError::SystemError;
};

class WorkerPool {
public:
    // threads in all, the caller of run() one of them (so threads - 1 are
    // started); at least one. A pool runs on all of them or is not made:
    // when a thread cannot be made (the system refuses it, or the memory for
    // its state runs out), those already started are stopped and joined and
    // ThreadsUnavailable is thrown (a baseline timed on fewer threads than it
    // names would be silently wrong).
    explicit WorkerPool(unsigned threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }
    // Runs job(t) for every t below size() at once, the caller as the last;
    // returns when all have, rethrowing the first exception a job threw.
    void run(const std::function<void(unsigned)>& job);

private:
    void stop();
    void work(unsigned index);
    void finish_one(std::exception_ptr error);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    const std::function<void(unsigned)>* job_ = nullptr;
    uint64_t generation_ = 0;
    unsigned pending_ = 0;
    bool stopping_ = false;
    std::exception_ptr error_;
};

// The threads a setting of 0 means: this machine's cores (at least one).
unsigned machine_threads();

}  // namespace cdvp
