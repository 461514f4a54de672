#!/usr/bin/env bash
# Writes every deterministic output of the commands the README and docs/ show into OUT, so that
# two builds can be compared byte for byte (a restructuring must change none):
#
#   scripts/deterministic-outputs.sh CDVP OUT      then   diff -r OUT_A OUT_B
#
# Deterministic: pairs, cycles, stalls, simulated phase times, resources, the
# settings, waveforms (without their $date), help texts. Left out: anything
# measured on this machine (wall times, software baselines, load, provenance).
set -euo pipefail

cdvp=$(realpath "$1")
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
out=$(realpath "$out")
# One preset directory for every build compared, so that settings' origins agree.
export CDVP_BOARDS=${CDVP_BOARDS:-$root/platform/boards}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# A report's frames and summary without what the machine measured.
strip_report() {
    /usr/bin/python3 - "$1" <<'EOF'
import json, sys
measured = ("wall", "native", "host", "load", "provenance", "calibration", "baselines", "command_line",
            "speedup", "repeat", "version", "amdahl_bound", "broadphase_share", "step_ns", "_ms", "timing_quality",
            "retimed")
def keep(key):
    return not any(word in key for word in measured)
def clean(value):
    if isinstance(value, dict):
        return {k: clean(v) for k, v in value.items() if keep(k)}
    if isinstance(value, list):
        return [clean(v) for v in value]
    return value
print(json.dumps(clean(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))
EOF
}

# NAME ARGS...: a run's pairs and its report's deterministic fields.
run_case() {
    local name=$1
    shift
    "$cdvp" run "$@" --pairs-out "$work/$name.pairs.csv" --report "$work/$name.json" -q
    cp "$work/$name.pairs.csv" "$out/$name.pairs.csv"
    strip_report "$work/$name.json" >"$out/$name.report.json"
}

scene=(--board adm-xrc-ii --scene spheres --objects 500 --frames 30 --m 24)
run_case default "${scene[@]}"
run_case cycle "${scene[@]}" --fidelity cycle
run_case pio-poll "${scene[@]}" --transfer pio --wait poll
run_case pcie --board pcie-gen3-x8 --scene spheres --objects 2000 --frames 5 --m 16
run_case fixed16 --board adm-xrc-ii --scene spheres --objects 3000 --frames 3 --m 8 --format fixed16
for trace in small hard_cases spellings bullet_pyramid; do
    run_case "trace-$trace" --board adm-xrc-ii --trace "$root/traces/$trace.csv" --m 4
done

# Waveforms: the VCD without its date, and the save file beside it.
"$cdvp" run --board adm-xrc-ii --scene spheres --objects 100 --frames 2 --m 4 --vcd "$work/waves.vcd" -q
awk '/^\$date/ { skip = 1 } !skip { print } skip && /\$end/ { skip = 0 }' "$work/waves.vcd" >"$out/waves.vcd"
for f in "$work"/waves*.gtkw "$work"/waves.*-states.txt; do
    [ -e "$f" ] && sed "s|$work|WORK|g" "$f" >"$out/$(basename "$f")"
done

"$cdvp" settings --json >"$out/settings.json"
"$cdvp" settings --board adm-xrc-ii --json >"$out/settings-adm-xrc-ii.json"
"$cdvp" settings --board pcie-gen3-x8 -c board.m=8 --json >"$out/settings-pcie-m8.json"

# A sweep's deterministic columns (the README's example, smaller).
"$cdvp" sweep --board adm-xrc-ii,pcie-gen3-x8 --set m=1,4,16 --set objects=50:800:x4 --frames 4 \
    --out "$work/sweep" --no-plots -q
/usr/bin/python3 - "$work/sweep/sweep.csv" >"$out/sweep.csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
measured = ("wall", "native", "host", "load", "provenance", "calibration", "checksum", "command_line",
            "speedup", "version")
columns = [c for c in rows[0] if not any(word in c for word in measured)]
w = csv.writer(sys.stdout)
w.writerow(columns)
for row in rows:
    w.writerow([row[c] for c in columns])
EOF
cp "$work/sweep/fit.csv" "$out/sweep-fit.csv"

# Bullet on the board: the pairs and simulated times of each frame.
"$cdvp" bullet --scene pyramid --frames 10 --board adm-xrc-ii --report "$work/bullet.json" -q
strip_report "$work/bullet.json" >"$out/bullet.report.json"

# fidelity: the simulated columns.
"$cdvp" fidelity --board adm-xrc-ii --scene spheres --objects 200 --frames 4 --m 8 --out "$work/fidelity" -q
cut -d, -f1-5,7- "$work/fidelity/fidelity.csv" >"$out/fidelity.csv"

for command in "" run fidelity settings sweep merge bullet record calibrate; do
    "$cdvp" $command --help >"$out/help-${command:-cdvp}.txt"
done
echo "deterministic outputs in $out"
