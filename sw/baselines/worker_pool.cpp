#include "sw/baselines/worker_pool.h"

#include <algorithm>
#include <new>
#include <string>
#include <system_error>

namespace cdvp {

namespace {

// Why a thread could not be made, in the system's words where it gave some.
std::string reason_of(const std::exception_ptr& failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const std::system_error& e) {
        return e.code().message();
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
    }
    return "an unknown failure";
}

}  // namespace

WorkerPool::WorkerPool(unsigned threads) {
    const unsigned workers = std::max(threads, 1u) - 1;
    try {
        workers_.reserve(workers);
        for (unsigned t = 0; t < workers; ++t) workers_.emplace_back([this, t] { work(t); });
    } catch (...) {
        // Whatever failed (a thread the system refused, memory for its state
        // run out), the started workers are stopped and joined before
        // anything else: the members they wait on go with this constructor,
        // and a condition variable destroyed under its waiters never returns.
        const std::size_t started = workers_.size() + 1;  // with the caller's
        stop();
        throw ThreadsUnavailable(std::to_string(workers + 1) + " threads asked; the system started " +
                                 std::to_string(started) + " (" + reason_of(std::current_exception()) +
                                 "); expected fewer");
    }
}

WorkerPool::~WorkerPool() { stop(); }

void WorkerPool::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    start_.notify_all();
    for (std::thread& worker : workers_) {
        if (worker.joinable()) worker.join();
    }
}

void WorkerPool::run(const std::function<void(unsigned)>& job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_ = &job;
        pending_ = size();
        error_ = nullptr;
        ++generation_;
    }
    start_.notify_all();
    std::exception_ptr mine;
    try {
        job(size() - 1);
    } catch (...) {
        mine = std::current_exception();
    }
    finish_one(mine);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    job_ = nullptr;
    if (error_) std::rethrow_exception(error_);
}

void WorkerPool::finish_one(std::exception_ptr error) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error && !error_) error_ = error;
    if (--pending_ == 0) done_.notify_all();
}

void WorkerPool::work(unsigned index) {
    uint64_t seen = 0;
    while (true) {
        const std::function<void(unsigned)>* job = nullptr;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            job = job_;
        }
        std::exception_ptr error;
        try {
            (*job)(index);
        } catch (...) {
            error = std::current_exception();
        }
        finish_one(error);
    }
}

unsigned machine_threads() { return std::max(std::thread::hardware_concurrency(), 1u); }

}  // namespace cdvp
