#!/usr/bin/env bash
# How still the software's time holds: the measurements behind docs/timing.md
# ("How still it holds"), each printed as a table. Run on the machine whose
# figures you want, with nothing of this project running beside it.
#
#   scripts/timing-stability.sh [SECTION...]    (default: all of them)
#
# Sections:
#   paper      four identical runs of the paper's point (adm-xrc-ii, 500 spheres, m = 24, 30 frames, sap)
#   pinned     the same with 40 frames and --repeat 3, pinned to CPU 0 beside a busy loop and alone (three pairs)
#   worked     the README's worked example after a fresh cdvp calibrate, six times, beside a CPU-bound job
#   sweep      the paper sweep (docs/results.md) three times, each after a fresh calibration: crossover and 500's speedup
#   grid       the README's 72-point sweep with shared timings and with each point timing its own:
#              timings used, falls in speedup from one m to the next, wall time (three of each, alternated)
#   bullet     cdvp bullet --scene boxes beside a busy loop and alone: the board's gains and verdict
#   neighbour  what CPU time leaves: the paper's point with all four baselines pinned to CPU 0, alone,
#              beside a busy loop on CPU 1 and beside a memory-streaming job on CPU 1 (shared cache and
#              memory bandwidth), three of each in turn: each baseline's native CPU time against alone
#
# CDVP (default build/sw/cli/cdvp) is the binary; WORK (default a temporary
# directory, removed at the end) holds the runs. The calibrations write
# WORK/profile.json, never the user's own profile.
set -euo pipefail
cd "$(dirname "$0")/.."
CDVP=${CDVP:-$PWD/build/sw/cli/cdvp}
[[ -x $CDVP ]] || { echo "timing-stability: no $CDVP (build first: scripts/build.sh)" >&2; exit 2; }
own_work=0
if [[ -z ${WORK:-} ]]; then WORK=$(mktemp -d); own_work=1; fi
mkdir -p "$WORK"
busy=()
cleanup() {
  for pid in "${busy[@]}"; do kill "$pid" 2>/dev/null || true; done
  if [[ $own_work == 1 ]]; then rm -rf "$WORK"; fi
}
trap cleanup EXIT
PROFILE=$WORK/profile.json
PAPER=(run --board adm-xrc-ii --scene spheres --objects 500 --m 24 --baseline sap --host-profile "$PROFILE")

# A busy loop, on CPU $1 or wherever the scheduler puts it; its pid in busy[].
start_busy() {
  if [[ -n ${1:-} ]]; then taskset -c "$1" sh -c 'while :; do :; done' & else sh -c 'while :; do :; done' & fi
  busy+=($!)
}
stop_busy() {
  for pid in "${busy[@]}"; do kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; done
  busy=()
}
load() { cut -d' ' -f1 /proc/loadavg; }
calibrate() { "$CDVP" calibrate -q --out "$PROFILE"; }

# Reads reports (paths as arguments): per baseline the speedup, native mean (us) and quality.
report_figures() {
  python3 - "$@" <<'EOF'
import json, sys
for path in sys.argv[1:]:
    s = json.load(open(path))["summary"]
    parts = []
    for name, b in sorted(s["baselines"].items()):
        q = b["timing_quality"]
        parts.append(f"{name} {b['speedup']:.3f}x native {b['mean_native_ns']/1e3:.1f} us "
                     f"({q['verdict']}; re-timed {q['frames_retimed']}, never clean {q['never_clean']}, slowed {q['frames_slowed']})")
    print("; ".join(parts))
EOF
}
# The spread, max/min - 1, of each baseline's speedup over the reports.
speedup_spread() {
  python3 - "$@" <<'EOF'
import json, sys
by = {}
for path in sys.argv[1:]:
    for name, b in json.load(open(path))["summary"]["baselines"].items():
        by.setdefault(name, []).append(b["speedup"])
for name, v in sorted(by.items()):
    print(f"| {name} | {', '.join(f'{x:.2f}' for x in v)} | {100 * (max(v) / min(v) - 1):.1f}% |")
EOF
}

section_paper() {
  echo "## paper: four identical runs of the paper's point (load $(load))"
  calibrate
  for k in 1 2 3 4; do "$CDVP" "${PAPER[@]}" --frames 30 -q --report "$WORK/paper-$k.json"; done
  report_figures "$WORK"/paper-?.json
  echo "| baseline | speedups | spread |"; echo "|---|---|---|"
  speedup_spread "$WORK"/paper-?.json
}

section_pinned() {
  echo "## pinned: 40 frames, --repeat 3, --pin-cpu 0, beside a busy loop on CPU 0 and alone (load $(load))"
  calibrate
  for k in 1 2 3; do
    start_busy 0
    "$CDVP" "${PAPER[@]}" --frames 40 --repeat 3 --pin-cpu 0 -q --report "$WORK/pinned-busy-$k.json"
    stop_busy
    "$CDVP" "${PAPER[@]}" --frames 40 --repeat 3 --pin-cpu 0 -q --report "$WORK/pinned-alone-$k.json"
  done
  python3 - "$WORK" <<'EOF'
import json, sys
work = sys.argv[1]
print("| pair | alone | beside the loop | beside / alone | quality beside |")
print("|---|---|---|---|---|")
for k in (1, 2, 3):
    a = json.load(open(f"{work}/pinned-alone-{k}.json"))["summary"]["baselines"]["sap"]
    b = json.load(open(f"{work}/pinned-busy-{k}.json"))["summary"]["baselines"]["sap"]
    q = b["timing_quality"]
    print(f"| {k} | {a['speedup']:.2f}x | {b['speedup']:.2f}x | {b['speedup'] / a['speedup']:.3f} | "
          f"{q['verdict']} (re-timed {q['frames_retimed']}, never clean {q['never_clean']}) |")
EOF
}

section_worked() {
  echo "## worked: the README's worked example after a fresh calibration, six times, beside a CPU-bound job (load $(load))"
  start_busy
  for k in 1 2 3 4 5 6; do
    calibrate
    "$CDVP" run --board adm-xrc-ii --scene spheres --objects 500 --frames 30 --m 24 --baseline sap,dbvt,brute,soa \
        --repeat 3 --host-profile "$PROFILE" -q --report "$WORK/worked-$k.json"
  done
  stop_busy
  report_figures "$WORK"/worked-?.json
  echo "| baseline | speedups | spread |"; echo "|---|---|---|"
  speedup_spread "$WORK"/worked-?.json
}

section_sweep() {
  echo "## sweep: the paper sweep three times, each after a fresh calibration (load $(load))"
  for k in 1 2 3; do
    calibrate
    "$CDVP" sweep --board adm-xrc-ii --set objects=20,50,100,200,300,500 --m 24 --frames 30 --baseline sap \
        --repeat 3 --host-profile "$PROFILE" --no-plots -q --out "$WORK/paper-sweep-$k"
  done
  python3 - "$WORK" <<'EOF'
import csv, sys
work = sys.argv[1]
rows = []
for k in (1, 2, 3):
    cross = [r for r in csv.DictReader(open(f"{work}/paper-sweep-{k}/crossover.csv")) if r["baseline"] == "sap"]
    s500 = [r for r in csv.DictReader(open(f"{work}/paper-sweep-{k}/sweep.csv")) if r["objects"] == "500"]
    rows.append((float(cross[0]["crossover_n"] or "nan"), cross[0]["how"], cross[0]["timing"], float(s500[0]["sap_speedup"])))
print("| sweep | crossover N | how | timing | speedup at 500 |")
print("|---|---|---|---|---|")
for k, (n, how, timing, s) in enumerate(rows, 1):
    print(f"| {k} | {n:.0f} | {how} | {timing} | {s:.3f}x |")
ns = [r[0] for r in rows]; ss = [r[3] for r in rows]
print(f"| spread | {100 * (max(ns) / min(ns) - 1):.1f}% | | | {100 * (max(ss) / min(ss) - 1):.1f}% |")
EOF
}

section_grid() {
  echo "## grid: the README's 72-point sweep, shared timings against each point its own (load $(load))"
  calibrate
  local grid=(sweep --board adm-xrc-ii,pcie-gen3-x8 --set m=1,2,4,8,16,24 --set objects=50:2000:x2 --frames 30
              --baseline sap,soa --jobs 2 --host-profile "$PROFILE" --no-plots -q)
  for k in 1 2 3; do
    for mode in shared own; do
      local extra=(); [[ $mode == own ]] && extra=(--software-timings none)
      local start=$(date +%s.%N)
      "$CDVP" "${grid[@]}" "${extra[@]}" --out "$WORK/grid-$mode-$k"
      echo "$mode $k $(echo "$(date +%s.%N) - $start" | bc)" >> "$WORK/grid-times"
    done
  done
  python3 - "$WORK" <<'EOF'
import csv, statistics, sys
from collections import defaultdict
work = sys.argv[1]
times = defaultdict(list)
for line in open(f"{work}/grid-times"):
    mode, k, seconds = line.split()
    times[mode].append(float(seconds))
print("| record | timings used (sap) | m steps where a speedup falls (sap, soa) | disturbed rows | sweep wall time, median of 3 (s) |")
print("|---|---|---|---|---|")
for mode in ("shared", "own"):
    rows = [r for r in csv.DictReader(open(f"{work}/grid-{mode}-1/sweep.csv")) if r["status"] == "ok"]
    ids = {r["sap_timing_id"] for r in rows} if mode == "shared" else {r["point"] for r in rows}
    falls = 0
    for name in ("sap", "soa"):
        lines = defaultdict(list)
        for r in rows:
            lines[(r["board"], r["objects"])].append((int(r["m"]), float(r[f"{name}_speedup"])))
        for points in lines.values():
            points.sort()
            falls += sum(1 for (m0, s0), (m1, s1) in zip(points, points[1:]) if s1 < s0 * (1 - 1e-9))
    disturbed = sum(1 for r in rows if "disturbed" in (r["sap_timing_quality"], r["soa_timing_quality"]))
    print(f"| {mode} | {len(ids)} of {len(rows)} rows | {falls} | {disturbed} | {statistics.median(times[mode]):.2f} "
          f"({', '.join(f'{t:.2f}' for t in times[mode])}) |")
print(f"ratio own / shared: {statistics.median(times['own']) / statistics.median(times['shared']):.2f}")
EOF
}

section_bullet() {
  echo "## bullet: cdvp bullet --scene boxes beside a busy loop on CPU 0 and alone, pinned to it (load $(load))"
  calibrate
  for k in 1 2 3; do
    for where in busy alone; do
      [[ $where == busy ]] && start_busy 0
      "$CDVP" bullet --scene boxes --frames 60 --board adm-xrc-ii --m 4 --warmup 1 --pin-cpu 0 \
          --host-profile "$PROFILE" -q --report "$WORK/bullet-$where-$k.json"
      stop_busy
    done
  done
  python3 - "$WORK" <<'EOF'
import json, sys
work = sys.argv[1]
print("| run | where | broad-phase gain | step gain | verdict | software timing |")
print("|---|---|---|---|---|---|")
for k in (1, 2, 3):
    for where in ("busy", "alone"):
        s = json.load(open(f"{work}/bullet-{where}-{k}.json"))["bullet"]["summary"]
        gain = s["broadphase_speedup"]
        q = s["timing_quality"]
        print(f"| {k} | {'beside the loop' if where == 'busy' else 'alone'} | {gain:.2f}x | {s['step_speedup']:.2f}x | "
              f"{'board wins' if gain > 1 else 'board loses'} | {q['verdict']} (never clean {q['never_clean']} of {q['frames_timed']}) |")
EOF
}

# A job that streams memory, on CPU $1: copies of a 256 MiB buffer, over and
# over, so that it holds the shared cache and the memory bandwidth.
start_streamer() {
  taskset -c "$1" python3 -c 'b = bytearray(1 << 28)
while True:
    c = bytes(b)' &
  busy+=($!)
}

section_neighbour() {
  echo "## neighbour: the paper's point, all four baselines, pinned to CPU 0: alone, beside a busy loop and beside a memory stream on CPU 1 (load $(load))"
  calibrate
  for k in 1 2 3; do
    for beside in alone loop stream; do
      [[ $beside == loop ]] && start_busy 1
      [[ $beside == stream ]] && start_streamer 1
      sleep 1
      "$CDVP" run --board adm-xrc-ii --scene spheres --objects 500 --m 24 --frames 40 --repeat 3 --pin-cpu 0 \
          --baseline sap,dbvt,brute,soa --host-profile "$PROFILE" -q --report "$WORK/neighbour-$beside-$k.json"
      stop_busy
    done
  done
  python3 - "$WORK" <<'EOF2'
import json, statistics, sys
work = sys.argv[1]
def means(beside):
    out = {}
    for k in (1, 2, 3):
        for name, b in json.load(open(f"{work}/neighbour-{beside}-{k}.json"))["summary"]["baselines"].items():
            out.setdefault(name, []).append(b["mean_native_ns"] / 1e3)
    return out
alone, loop, stream = means("alone"), means("loop"), means("stream")
print("| baseline | alone: CPU time a frame (us) | beside a busy loop | beside a memory stream |")
print("|---|---|---|---|")
for name in sorted(alone):
    a = statistics.median(alone[name])
    cells = [f"{', '.join(f'{v:.1f}' for v in alone[name])}"]
    for other in (loop, stream):
        o = statistics.median(other[name])
        cells.append(f"{', '.join(f'{v:.1f}' for v in other[name])} ({100 * (o / a - 1):+.1f}%)")
    print(f"| {name} | " + " | ".join(cells) + " |")
EOF2
}

sections=("$@")
[[ ${#sections[@]} -gt 0 ]] || sections=(paper pinned worked sweep grid bullet neighbour)
echo "# timing stability on $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) CPUs, $(date -u +%Y-%m-%d)"
for s in "${sections[@]}"; do
  declare -F "section_$s" > /dev/null || { echo "timing-stability: no section '$s' (see the header)" >&2; exit 2; }
  "section_$s"
  echo
done
