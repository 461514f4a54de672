// Temporaries that must not outlive the process: when it is killed by a
// signal whose default action ends it (SIGINT, SIGTERM, SIGHUP, SIGPIPE,
// SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU and SIGXFSZ from ulimit, SIGVTALRM,
// SIGPROF), a signal handler unlinks every registered path and re-raises the
// signal, so the process still ends with the conventional status 128+signal.
// SIGKILL cannot be caught: its temporaries stay (named *.part-*).
#pragma once

#include <csignal>
#include <string>

namespace cdvp {

class TemporaryRegistry {
public:
    // Registers 'path' (installing the handlers on first use; a signal the
    // process ignores, as under nohup, stays ignored). Returns a slot for
    // release(). Throws std::length_error when the fixed table is full or the
    // path is longer than PATH_MAX: the handler may not allocate.
    static int hold(const std::string& path);
    // Forgets the slot (the path was renamed or removed); -1 is ignored.
    static void release(int slot) noexcept;
    // Installs the handlers now (once per process): a caller that handles
    // the same signals itself for a while (a sweep) installs its own after.
    static void install_handlers();
    // The signals whose default action the handler keeps.
    static const int kSignals[12];
};

// Blocks the cleanup signals for its lifetime, so that a commit's renames
// and their rollback are never cut short; a signal that arrives meanwhile
// is delivered when the block ends.
class CleanupSignalsBlocked {
public:
    CleanupSignalsBlocked();
    ~CleanupSignalsBlocked();
    CleanupSignalsBlocked(const CleanupSignalsBlocked&) = delete;
    CleanupSignalsBlocked& operator=(const CleanupSignalsBlocked&) = delete;

private:
    sigset_t previous_;
};

}  // namespace cdvp
