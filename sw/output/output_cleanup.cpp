#include "sw/output/output_cleanup.h"

#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <stdexcept>

namespace cdvp {

namespace {

// A fixed table: the handler reads it without locks or allocation. A slot's
// path is written before the slot is marked in use, and the slot is marked
// free before the path may be overwritten.
constexpr int kSlots = 32;
char g_paths[kSlots][PATH_MAX];
volatile std::sig_atomic_t g_in_use[kSlots];
bool g_installed = false;

extern "C" void unlink_temporaries_and_reraise(int signal_number) {
    const int saved_errno = errno;
    for (int k = 0; k < kSlots; ++k) {
        if (g_in_use[k]) unlink(g_paths[k]);  // async-signal-safe
    }
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    sigaction(signal_number, &default_action, nullptr);
    // Blocked while this handler runs; delivered with the default action
    // (termination) as soon as it returns.
    raise(signal_number);
    errno = saved_errno;
}

}  // namespace

void TemporaryRegistry::install_handlers() {
    if (g_installed) return;
    g_installed = true;
    for (int signal_number : TemporaryRegistry::kSignals) {
        struct sigaction previous {};
        if (sigaction(signal_number, nullptr, &previous) != 0 || previous.sa_handler == SIG_IGN) continue;
        struct sigaction action {};
        action.sa_handler = unlink_temporaries_and_reraise;
        sigemptyset(&action.sa_mask);
        for (int other : TemporaryRegistry::kSignals) sigaddset(&action.sa_mask, other);
        sigaction(signal_number, &action, nullptr);
    }
}

const int TemporaryRegistry::kSignals[12] = {SIGINT,  SIGTERM, SIGHUP,  SIGPIPE, SIGQUIT,   SIGALRM,
                                             SIGUSR1, SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF};

int TemporaryRegistry::hold(const std::string& path) {
    if (path.size() >= PATH_MAX) throw std::length_error(path + ": path too long for a temporary");
    TemporaryRegistry::install_handlers();
    for (int k = 0; k < kSlots; ++k) {
        if (g_in_use[k]) continue;
        std::memcpy(g_paths[k], path.c_str(), path.size() + 1);
        std::atomic_signal_fence(std::memory_order_seq_cst);
        g_in_use[k] = 1;
        return k;
    }
    throw std::length_error("more than " + std::to_string(kSlots) + " temporary files at once");
}

void TemporaryRegistry::release(int slot) noexcept {
    if (slot < 0 || slot >= kSlots) return;
    g_in_use[slot] = 0;
    std::atomic_signal_fence(std::memory_order_seq_cst);
}

CleanupSignalsBlocked::CleanupSignalsBlocked() {
    sigset_t blocked;
    sigemptyset(&blocked);
    for (int signal_number : TemporaryRegistry::kSignals) sigaddset(&blocked, signal_number);
    sigprocmask(SIG_BLOCK, &blocked, &previous_);
}

CleanupSignalsBlocked::~CleanupSignalsBlocked() { sigprocmask(SIG_SETMASK, &previous_, nullptr); }

}  // namespace cdvp
