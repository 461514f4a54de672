#!/usr/bin/env python3
"""Puts each command's current --help into docs/cli.md, the command-line
reference, replacing the fenced block that starts with the same Usage line
(cli_tests checks them verbatim).

    scripts/cli-help.py [path/to/cdvp]    (default: build/sw/cli/cdvp)
"""
import pathlib
import subprocess
import sys

root = pathlib.Path(__file__).resolve().parent.parent
binary = sys.argv[1] if len(sys.argv) > 1 else str(root / "build/sw/cli/cdvp")
page = root / "docs" / "cli.md"
text = page.read_text()
for command in ["", "run", "fidelity", "settings", "sweep", "merge", "bullet", "record", "calibrate", "rtl-variants"]:
    args = [binary] + ([command] if command else []) + ["--help"]
    help_text = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    # The block whose first line names the same command ("Usage: cdvp run "):
    # the rest of the line may have been wrapped differently since.
    usage = " ".join(help_text.split("\n", 1)[0].split()[:3]) + " "
    start = text.find("```\n" + usage)
    if start < 0:
        sys.exit(f"docs/cli.md has no block starting with {usage!r}")
    end = text.find("```\n", start + 4)
    text = text[: start + 4] + help_text + text[end:]
page.write_text(text)
