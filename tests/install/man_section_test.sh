#!/usr/bin/env bash
# man_section_test.sh CDVP MAN_PAGE COMMAND
# man_section_test.sh CDVP MAN_PAGE commands TESTED...
# man_section_test.sh CDVP MAN_PAGE presets BOARDS_DIR
# The man page's section for COMMAND ("OPTIONS OF COMMAND"), rendered as plain
# text, must equal `cdvp COMMAND --help` line for line. "commands" checks
# instead that the page has a section for every command `cdvp --help` lists
# and for no other, and that TESTED (the commands with a test of their own)
# are those same commands. "presets" checks that FILES names every preset.
set -euo pipefail
cdvp=$1 page=$2 command=$3
shift 3
fail() { echo "man page: $*" >&2; exit 1; }
if [ ! -f "$page" ]; then
  # Skipped where help2man is missing, unless CI asks for the page.
  [ -z "${CDVP_REQUIRE_MAN_PAGE:-}" ] && { echo "help2man missing: no man page at $page"; exit 77; }
  fail "no man page at $page"
fi
# Plain ASCII, no overstrikes, lines as wide as they come (.nf blocks keep theirs).
text=$(groff -man -Tascii -P-cbou -rLL=300n "$page" 2>&1) || fail "groff could not render $page: $text"
sections=$(sed -n 's/^OPTIONS OF \(.*\)$/\1/p' <<< "$text" | tr A-Z a-z)
if [ "$command" = commands ]; then
  listed=$("$cdvp" --help | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p')
  [ -n "$listed" ] || fail "cdvp --help lists no commands"
  [ "$(sort <<< "$listed")" = "$(sort <<< "$sections")" ] ||
    fail "its sections ($(echo $sections)) are not the commands cdvp --help lists ($(echo $listed))"
  [ "$(sort <<< "$listed")" = "$(printf '%s\n' "$@" | sort)" ] ||
    fail "the commands with a test ($*) are not those cdvp --help lists ($(echo $listed)): tests/CMakeLists.txt"
  echo "man page: a section for each of $(echo $listed)"
  exit 0
fi
if [ "$command" = presets ]; then
  # FILES names every preset the boards directory ($1) holds.
  for preset in "$1"/*.json; do
    name=$(basename "$preset" .json)
    grep -q "presets:.*\b$name\b" <<< "$text" || fail "FILES does not name the preset $name ($preset)"
  done
  echo "man page: every preset of $1 named"
  exit 0
fi
title=$(tr a-z A-Z <<< "$command")
grep -qx "OPTIONS OF $title" <<< "$text" || fail "no section OPTIONS OF $title"
# The section: the lines under its heading (the help sits at the left margin)
# up to the next heading, a line of capitals alone; blank lines at its end dropped.
section=$(awk -v h="OPTIONS OF $title" '$0 == h {on = 1; next} on && /^[A-Z][A-Z -]+$/ {exit} on' <<< "$text")
help=$("$cdvp" "$command" --help) || fail "cdvp $command --help failed"
if [ "$section" != "$help" ]; then
  diff <(echo "$help") <(echo "$section") | head -20 >&2
  fail "the section OPTIONS OF $title differs from 'cdvp $command --help' (< help, > man page)"
fi
echo "man page: OPTIONS OF $title equals cdvp $command --help ($(wc -l <<< "$help") lines)"
