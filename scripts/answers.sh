#!/usr/bin/env bash
# What fits and what it costs, answered by two sweeps (docs/answers.md):
#
#   scripts/answers.sh [OUT]      (default OUT: answers/; CDVP=path/to/cdvp, JOBS=2)
#
#   OUT/formats/  every number format on both presets at N = 500 .. 65,536: fit.csv
#                 (largest m, lanes, extra pairs), largest-m-BOARD.png, lanes-extra-BOARD.png
#   OUT/speedup/  float32 and fixed16, m = 4 .. 32, N = 100 .. 65,536, against Bullet's sweep
#                 and prune: time-BOARD.png, speedup-BOARD-sap.png, crossover.csv, fit.csv
#
# Points that do not fit a device are rows with their reason, not failures. Each sweep
# resumes when rerun into the same OUT.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cdvp=${CDVP:-$root/build/sw/cli/cdvp}
out=${1:-answers}
jobs=${JOBS:-2}
boards=adm-xrc-ii,pcie-gen3-x8

# Extra pairs do not depend on m: one m that runs everywhere (in SSRAM tiles past the block RAMs).
"$cdvp" sweep --board "$boards" --set format=float32,fixed32,fixed24,fixed18,fixed16,fixed12,fixed9,fixed8 \
    --set objects=256:65536:x2 --m 8 --frames 6 --warmup 1 --jobs "$jobs" --out "$out/formats"

# Board time and speedup against N, one line per m and format; 12 frames, means after 2.
"$cdvp" sweep --board "$boards" --set format=float32,fixed16 --set m=4,8,11,16,24,32 \
    --set objects=100,300,1000,3000,10000,30000,65536 --frames 12 --warmup 2 --baseline sap \
    --jobs "$jobs" --out "$out/speedup"
