"""Shared helpers: the CLI the package runs, run directly for comparison."""

import subprocess

import pytest

import cdvp

# A small scene: each run takes a few tens of milliseconds.
SMALL = {"board": "adm-xrc-ii", "scene": "spheres", "objects": 40, "frames": 2}


def cli_words(options):
    """The command line cdvp.run builds for these keywords, as a list of words."""
    words = []
    for name, value in options.items():
        words += ["--" + name.replace("_", "-"), str(value)]
    return words


@pytest.fixture(scope="session")
def cli():
    """Runs `cdvp ARGS...`; returns the completed process (stdout, stderr as text)."""
    binary = cdvp.find_binary()

    def run(*args):
        return subprocess.run([binary, *args], capture_output=True, text=True, check=False)

    return run
