"""Where the package finds the cdvp binary and the board presets (docs/python.md: Install)."""

import os

from . import _paths

_HERE = os.path.dirname(os.path.abspath(__file__))


def _executable(path):
    return os.path.isfile(path) and os.access(path, os.X_OK)


def find_binary():
    """The cdvp the runs use: PREFIX/bin/cdvp beside an installed package, else
    the build tree's (its path fixed when the module was built), else $CDVP_BINARY.
    Raises InputError when there is none."""
    installed = os.path.normpath(os.path.join(_HERE, _paths.INSTALLED_BINARY))
    for candidate in (installed, _paths.BUILD_BINARY, os.environ.get("CDVP_BINARY", "")):
        if candidate and _executable(candidate):
            return candidate
    from ._errors import InputError

    raise InputError("cdvp: no cdvp binary to run: install cdvp beside the package, keep its build tree, "
                     "or set $CDVP_BINARY", 2)


def use_installed_boards():
    """Points $CDVP_BOARDS at PREFIX/share/cdvp/boards for an installed package
    (unless set), so that this process reads the presets the installed binary
    reads; the extension's own fallback is the source tree it was built from."""
    boards = os.path.normpath(os.path.join(_HERE, _paths.INSTALLED_BOARDS))
    if not os.environ.get("CDVP_BOARDS") and os.path.isdir(boards):
        os.environ["CDVP_BOARDS"] = boards
