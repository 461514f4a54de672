#!/usr/bin/env bash
# install_test.sh BUILD_DIR CMAKE VERSION [man]
# Installs the build into a temporary prefix and runs the installed binary from
# a directory outside the tree with CDVP_BOARDS unset: it must find the
# installed presets (also after the prefix is moved), print the project's
# version, and ship the docs. With "man": the man page must exist, render, and
# carry every command that `cdvp --help` lists with that command's --help.
set -euo pipefail
build=$1 cmake=$2 version=$3 part=${4:-binary}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "install test: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$work/prefix" > "$work/install.log" || fail "cmake --install failed: $(cat "$work/install.log")"
mkdir "$work/elsewhere"
cd "$work/elsewhere"
unset CDVP_BOARDS

if [ "$part" = man ]; then
  page="$work/prefix/share/man/man1/cdvp.1"
  if [ ! -f "$page" ]; then
    # Skipped where help2man is missing, unless CI asks for the page.
    if [ -z "${CDVP_REQUIRE_MAN_PAGE:-}" ] && grep -q "CDVP_HELP2MAN:FILEPATH=.*NOTFOUND" "$build/CMakeCache.txt"; then
      echo "help2man missing: no man page"
      exit 77
    fi
    fail "no man page at $page"
  fi
  text=$(MANWIDTH=200 man -l "$page" 2> "$work/man.err" | col -b) || fail "man -l $page: $(cat "$work/man.err")"
  commands=$("$work/prefix/bin/cdvp" --help | sed -n '/^Commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z]*\) .*/\1/p')
  [ -n "$commands" ] || fail "cdvp --help lists no commands"
  for command in $commands; do
    title=$(echo "$command" | tr a-z A-Z)
    grep -q "^OPTIONS OF $title\$" <<< "$text" || fail "the man page has no section for '$command'"
    grep -q "Usage: cdvp $command " <<< "$text" || fail "the man page lacks 'cdvp $command --help'"
  done
  grep -q "^ *CDVP_BOARDS" <<< "$text" || fail "the man page does not document CDVP_BOARDS"
  for section in EXAMPLES ENVIRONMENT FILES "SEE ALSO"; do
    grep -q "^$section\$" <<< "$text" || fail "the man page has no $section section"
  done
  grep -q "cdvp sweep --board" <<< "$text" || fail "the man page's EXAMPLES lack a sweep"
  echo "man page: $(echo $commands) documented"
  exit 0
fi

# The installed copy of the paper's preset is renamed, so a report naming the
# new name proves the installed presets were read, not the source tree's.
sed -i '0,/"name": "adm-xrc-ii"/s//"name": "adm-xrc-ii (installed copy)"/' \
  "$work/prefix/share/cdvp/boards/adm-xrc-ii.json"
run_from() {  # run_from PREFIX: a short run on the paper's board
  "$1/bin/cdvp" run --board adm-xrc-ii --scene spheres --objects 20 --frames 2 -q --report report.json ||
    fail "the binary installed in $1 failed to run on adm-xrc-ii"
  grep -qF '"board": "adm-xrc-ii (installed copy)"' report.json ||
    fail "the binary installed in $1 did not read its own presets: $(grep '"board"' report.json)"
}
run_from "$work/prefix"
mv "$work/prefix" "$work/moved"
run_from "$work/moved"

[ "$("$work/moved/bin/cdvp" --version)" = "cdvp $version" ] || fail "--version printed '$("$work/moved/bin/cdvp" --version)'"
for doc in README.md LICENSE docs/numerics.md docs/fidelity.png; do
  [ -f "$work/moved/share/doc/cdvp/$doc" ] || fail "share/doc/cdvp/$doc not installed"
done
for schema in run-report sweep-row; do
  python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$work/moved/share/cdvp/schema/$schema.schema.json" ||
    fail "share/cdvp/schema/$schema.schema.json not installed, or not JSON"
done
for preset in adm-xrc-ii adm-xrc-ii-64 alveo-u250 pcie-gen3-x8; do
  [ -f "$work/moved/share/cdvp/boards/$preset.json" ] || fail "preset $preset not installed"
done
echo "installed binary ran from $work/moved with its own presets"
