#!/usr/bin/env bash
# Frame pipelining against one frame at a time, answered by one sweep (docs/answers.md, "Pipelining"):
#
#   scripts/pipelining.sh [OUT]      (default OUT: pipelining/; CDVP=path/to/cdvp, JOBS=2)
#
#   OUT/traces/    Bullet's falling spheres recorded at N = 20 .. 750 (cdvp record): pipelined frames
#                  must be known ahead, so the sweep replays traces instead of stepping an application
#   OUT/sweep/     one and two box banks x every interrupt and board interrupts x m = 6, 12, 24 on both
#                  presets, against all four baselines (fast engine: the analytic level times one
#                  frame at a time)
#   OUT/pipelining.csv, OUT/pipelining.md: the crossover N per baseline at the largest m that fits each
#                  board, and throughput against latency at N = 500
#
# The sweep resumes when rerun into the same OUT.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cdvp=${CDVP:-$root/build/sw/cli/cdvp}
out=${1:-pipelining}
jobs=${JOBS:-2}
sizes="20 30 50 75 100 150 200 300 500 750"

mkdir -p "$out/traces"
traces=()
for n in $sizes; do
    trace="$out/traces/spheres-$n.csv"
    [ -s "$trace" ] || "$cdvp" record --scene bullet-spheres --objects "$n" --frames 12 --out "$trace" -q
    traces+=("$trace")
done
list=$(IFS=,; echo "${traces[*]}")

"$cdvp" sweep --board adm-xrc-ii,pcie-gen3-x8 --trace "$list" --set box-banks=1,2 --set interrupts=every,board \
    --set m=6,12,24 --fidelity fast --warmup 2 --baseline sap,dbvt,brute,soa --jobs "$jobs" --no-plots -q \
    --out "$out/sweep"

python3 "$root/scripts/pipelining-table.py" "$out" | tee "$out/pipelining.md"
