#!/usr/bin/env bash
# Which board at which N, against software: the all-pairs board and the grid board
# (docs/grid_board.md) on both presets, answered by sweeps (docs/answers.md, "Beyond brute force"):
#
#   scripts/grid-answers.sh [OUT]      (default OUT: grid-answers/; CDVP=path/to/cdvp)
#
# A loaded machine may shorten it: SOFTWARE_OBJECTS (the N timed against Bullet), BOARD_OBJECTS (the
# N run on the boards alone; empty: that sweep is skipped), M (the m swept) and FRAMES/WARMUP replace
# the lists below.
#
#   OUT/software/  board.algorithm x m x N = 100 .. 10^5 against Bullet's sweep and prune (sap) and
#                  dynamic tree (dbvt): time-BOARD.png, speedup-BOARD-BASELINE.png, crossover.csv
#   OUT/million/   the same boards at N = 10^6, without software: Bullet's sap inserts a world's
#                  proxies in O(N^2) (about 3 CPU minutes at 10^5 boxes, so hours at 10^6), and a
#                  frame of either takes seconds there; SOFTWARE_OBJECTS=1000000 times them anyway
#
# The analytic level times every point (exact where its bound holds; docs/analytic.md), in the
# sweep's own process. Points that do not fit a device (the ADM-XRC-II's SSRAM at 10^6 boxes,
# m = 32 beside its 144 block RAMs) are rows with their reason. Each sweep resumes when rerun.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cdvp=${CDVP:-$root/build/sw/cli/cdvp}
out=${1:-grid-answers}
common=(--board adm-xrc-ii,pcie-gen3-x8 --set board.algorithm=all_pairs,grid --set m="${M:-4,8,11,32}"
        --fidelity analytic --frames "${FRAMES:-4}" --warmup "${WARMUP:-2}")

"$cdvp" sweep "${common[@]}" --set objects="${SOFTWARE_OBJECTS:-100,300,1000,3000,10000,30000,100000}" \
    --baseline sap,dbvt --out "$out/software"
board_objects=${BOARD_OBJECTS-1000000}
if [[ -n $board_objects ]]; then
    "$cdvp" sweep "${common[@]}" --set objects="$board_objects" --out "$out/million"
fi
