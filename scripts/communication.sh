#!/usr/bin/env bash
# The communication design space, answered by two sweeps (docs/answers.md, "Communication"):
#
#   scripts/communication.sh [OUT]      (default OUT: communication/; CDVP=path/to/cdvp, JOBS=2)
#
#   OUT/strategies/  every upload x pair format x interrupt policy on both presets, N = 20 .. 750,
#                    against all four baselines, in a scene where a tenth of the spheres move
#   OUT/moving/      full against delta uploads at N = 500 against the share of moving spheres
#   OUT/crossover-by-strategy.csv, OUT/delta-break-even.csv, OUT/crossover-by-strategy.png
#
# Each sweep resumes when rerun into the same OUT.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cdvp=${CDVP:-$root/build/sw/cli/cdvp}
out=${1:-communication}
jobs=${JOBS:-2}
boards=adm-xrc-ii,pcie-gen3-x8

# m = 12: the largest that fits the paper's device at 750 boxes; 12 frames, means after 2.
"$cdvp" sweep --board "$boards" --set upload=full,delta --set pair-format=list,counted,bitmap \
    --set interrupts=every,board --set objects=20,30,50,75,100,150,200,300,500,750 --m 12 --moving 0.1 \
    --frames 12 --warmup 2 --baseline sap,dbvt,brute,soa --jobs "$jobs" --no-plots -q --out "$out/strategies"

"$cdvp" sweep --board "$boards" --set upload=full,delta --set moving=0,0.05,0.1,0.2,0.4,0.6,0.8,0.9,1 \
    --objects 500 --m 12 --frames 6 --warmup 2 --jobs "$jobs" --no-plots -q --out "$out/moving"

python3 "$root/scripts/communication-table.py" "$out" | tee "$out/tables.md"
gnuplot -e "data='$out/crossover-by-strategy.dat'; out='$out/crossover-by-strategy.png'" \
    "$root/scripts/communication-figure.gp"
