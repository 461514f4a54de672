#!/usr/bin/env bash
# gtkwave_test.sh CDVP FORMAT
# Opens the waveforms of a two-frame run (`cdvp run --vcd`, FORMAT vcd or
# fst; rtl: the board RTL's own, --fidelity rtl) with their save file in real
# GTKWave under Xvfb, as a user would with `gtkwave -a waves.gtkw waves.vcd`,
# and lets check_view.tcl (check_rtl_view.tcl) judge what shows.
# Skipped (77) where gtkwave or xvfb-run is missing, unless
# CDVP_REQUIRE_GTKWAVE is set (CI: scripts/setup.sh installs both).
set -euo pipefail
format=$2
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "gtkwave test: $*" >&2; exit 1; }

for tool in gtkwave xvfb-run; do
  if ! command -v "$tool" > /dev/null; then
    [ -z "${CDVP_REQUIRE_GTKWAVE:-}" ] || fail "$tool not found (scripts/setup.sh installs it)"
    echo "$tool not found: the waveforms are not opened in GTKWave"
    exit 77
  fi
done

cdvp=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
script=check_view.tcl
if [ "$format" = rtl ]; then
  format=vcd
  script=check_rtl_view.tcl
  "$cdvp" run --board adm-xrc-ii --fidelity rtl --scene spheres --objects 40 --frames 2 --m 8 -q \
    --vcd waves.vcd || fail "cdvp run --fidelity rtl --vcd failed"
  filters="controller"  # the RTL's dump names no DMA state
  idle="1 idle"         # the RTL's controller is one-hot
else
  "$cdvp" run --board adm-xrc-ii --scene spheres --objects 40 --frames 2 --m 4 -q \
    --vcd "waves.$format" --vcd-format "$format" || fail "cdvp run --vcd failed"
  filters="controller dma"
  idle="0 idle"
fi
# A translate filter file for each named state the dump holds, and no other.
[ "$(ls *-states.txt | tr '\n' ' ')" = "$(for f in $filters; do printf '%s ' "waves.$f-states.txt"; done)" ] ||
  fail "filter files $(ls *-states.txt | tr '\n' ' ')where the dump names the states of: $filters"
grep -qx "$idle" waves.controller-states.txt || fail "waves.controller-states.txt: $(cat waves.controller-states.txt)"
# A screen larger than the window the save file asks for, so none of it is cut.
status=0
timeout 120 xvfb-run -a -s "-screen 0 1600x1000x24" \
  gtkwave -S "$here/$script" -a waves.gtkw "waves.$format" > gtkwave.log 2>&1 || status=$?
grep '^check:' gtkwave.log || true
[ "$status" -eq 0 ] || fail "gtkwave exited with $status: $(tail -5 gtkwave.log)"
grep -qx 'check: PASS' gtkwave.log || fail "GTKWave does not show the waveforms as the save file asks"
