"""cdvp's exceptions: one class per exit status of the command line.

Each carries the command's own one-line message ("cdvp run: ...") and its
status, so a script may tell bad input from a simulated fault as a shell
script tells them by the exit status (docs/python.md: Errors).
"""

import signal


class Error(Exception):
    """A call that ended as the command would have ended with a non-zero status."""

    status = 1

    def __init__(self, message, status=None):
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status


class InternalError(Error):
    """Status 1: a failure inside cdvp (a bug), or a run killed by a signal."""

    status = 1


class InputError(Error):
    """Status 2: bad input, refused before any work (an unknown option, a board that does not fit)."""

    status = 2


class DeviceFault(Error):
    """Status 3: the simulated system faulted (a DMA fault, a board error: docs/faults.md)."""

    status = 3


class SystemFailure(Error):
    """Status 4: the operating system failed what the input was fine for (a full disk, an I/O error)."""

    status = 4


_BY_STATUS = {cls.status: cls for cls in (InternalError, InputError, DeviceFault, SystemFailure)}


def error_class(status):
    """The class of an exit status; any status cdvp does not define is an InternalError."""
    return _BY_STATUS.get(status, InternalError)


def raise_for_outcome(outcome, where="(the reason is on standard error)"):
    """Raises what a sweep's outcome says went wrong: KeyboardInterrupt for a
    Ctrl-C, InternalError for another stop signal, the class of its exit
    status for a failed point, whose reason cdvp printed where `where` says."""
    if outcome["stop_signal"] == signal.SIGINT:
        raise KeyboardInterrupt
    if outcome["stop_signal"]:
        raise InternalError(f"cdvp.sweep: stopped by signal {outcome['stop_signal']}", 1)
    if outcome["status"] != 0:
        status = outcome["status"]
        raise error_class(status)(f"cdvp.sweep: ended with status {status} after {outcome['points']} points {where}",
                                  status)
