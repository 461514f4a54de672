// Temporaries that must not outlive the process: when it is killed by a
// signal whose default action ends it (SIGINT, SIGTERM, SIGHUP, SIGPIPE,
// SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGXCPU and SIGXFSZ from ulimit, SIGVTALRM,
// SIGPROF), a signal handler unlinks every registered path and re-raises the
// signal, so the process still ends with the conventional status 128+signal.
// SIGKILL cannot be caught: its temporaries stay (named *.part-*). A signal
// the process handles itself or ignores keeps its handler: an interpreter's
// Ctrl-C stays its own, and a temporary is then removed by the code that
// made it as the interrupted call unwinds.
#pragma once

#include <csignal>
#include <string>

namespace cdvp {

class TemporaryRegistry {
public:
    // Registers 'path' (installing the handlers on first use, for good unless
    // a HandlersInstalled scope is open; a signal the process ignores, as
    // under nohup, or handles itself stays so). Returns a slot for
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

// The handlers installed for a scope, for a process that is not cdvp's own
// (the Python module): on leaving it, every signal's previous action is put
// back, so that cdvp's handlers are in place only around its own work.
// Scopes nest; one opened while the handlers are installed for good does
// nothing.
class HandlersInstalled {
public:
    HandlersInstalled();
    ~HandlersInstalled();
    HandlersInstalled(const HandlersInstalled&) = delete;
    HandlersInstalled& operator=(const HandlersInstalled&) = delete;

private:
    bool restores_ = false;
    struct sigaction previous_[12] {};
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
