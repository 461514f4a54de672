#!/usr/bin/env bash
# Where the board wins on time and where on energy, and by how much: the 2007 set-up (adm-xrc-ii:
# the paper's board in a Pentium 4) and today's (alveo-u250: an Alveo U250 on PCIe Gen3 x16 in this
# project's two-core EPYC host), with one core and with all of them (docs/answers.md, "Energy"):
#
#   scripts/energy-answers.sh [OUT]      (default OUT: energy-answers/; CDVP=path/to/cdvp)
#
#   OUT/2007/, OUT/today/   the two sweeps (sweep.csv, crossover.csv, their figures)
#   OUT/energy-table.md     crossover N on time and on energy per software and thread count, and
#                           both ratios at N = 500, 3,200 and 10,000 (scripts/energy-table.py)
#   OUT/energy.png          energy a frame against N, the board's and the software's, one panel a set-up
#
# OBJECTS replaces the N swept. The software is timed on this machine and scaled to each preset's host
# by a host profile (cdvp calibrate), so run one first; each sweep resumes when rerun.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cdvp=${CDVP:-$root/build/sw/cli/cdvp}
out=${1:-energy-answers}
objects=${OBJECTS:-100,150,200,300,500,800,1600,3200,10000}
common=(--set objects="$objects" --frames 12 --baseline sap,sap_mt --jobs 1)

# The paper's board holds m = 24 up to 1,024 boxes in block RAM and m = 11 in SSRAM tiles beyond.
"$cdvp" sweep --board adm-xrc-ii --set m=11,24 "${common[@]}" --out "$out/2007"
"$cdvp" sweep --board alveo-u250 --set m=32 --set threads=1,2 "${common[@]}" --out "$out/today"
python3 "$root/scripts/energy-table.py" "$out/2007/sweep.csv" "$out/today/sweep.csv" --dat "$out/energy.dat" \
    --at 500,3200,10000 >"$out/energy-table.md"
gnuplot -e "data='$out/energy.dat'; out='$out/energy.png'" "$root/scripts/energy-figure.gp"
echo "wrote $out/energy-table.md and $out/energy.png"
