#!/usr/bin/env bash
# The boards against the strongest software (docs/answers.md, "Against the fastest software"):
# both boards (all-pairs and grid) on the paper's set-up and today's card, on every scene
# family (docs/scenes.md), against --baseline best (docs/baselines.md) and, up to 10,000
# boxes, Bullet's sweep and prune as the labelled old row:
#
#   scripts/best-answers.sh [OUT]      (default OUT: best-answers/; CDVP=path/to/cdvp)
#
#   OUT/small/    N = 500, 2,000, 10,000 against best and sap: sweep.csv, crossover.csv
#   OUT/large/    N = 100,000 against best (Bullet's sap takes minutes to build its world there)
#   OUT/table.md  the table docs/answers.md shows (scripts/best-table.py)
#
# The analytic level times every board (exact where its bound holds; docs/analytic.md). FRAMES,
# WARMUP, SCENES, SMALL and LARGE replace the lists below. Each sweep resumes when rerun.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cdvp=${CDVP:-$root/build/sw/cli/cdvp}
out=${1:-best-answers}
common=(--board adm-xrc-ii,alveo-u250 --set board.algorithm=all_pairs,grid --scene "${SCENES:-spheres,pile,heavy,planar,brownian}"
        --fidelity analytic --frames "${FRAMES:-12}" --warmup "${WARMUP:-2}" --jobs 1)

"$cdvp" sweep "${common[@]}" --set objects="${SMALL:-500,2000,10000}" --baseline best,sap --out "$out/small"
"$cdvp" sweep "${common[@]}" --set objects="${LARGE:-100000}" --baseline best --out "$out/large"
python3 "$root/scripts/best-table.py" "$out/small/sweep.csv" "$out/large/sweep.csv" > "$out/table.md"
cat "$out/table.md"
