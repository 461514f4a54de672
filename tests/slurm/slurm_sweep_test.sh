#!/bin/bash
# docs/sweep-slurm.sh on a real Slurm: munge, slurmctld and slurmd of this
# test's own on the loopback address (one node, two CPUs), the documented job
# array and its dependent merge. Checks that the merged rows equal a local
# sweep's outside the measured columns, and that a task killed midway and
# submitted again runs only its shard's missing points.
#
#   tests/slurm/slurm_sweep_test.sh CDVP SOURCE_DIR
# Exits 77 (skipped, one line saying why) where Slurm cannot run: its daemons
# are not installed (Debian: slurmctld slurmd munge) or this is not root;
# with CDVP_REQUIRE_SLURM=1 (CI, where scripts/setup.sh installs them) that
# is a failure instead.
set -euo pipefail
cdvp=$(realpath "$1")
source_dir=$(realpath "$2")
skip() {
  if [ "${CDVP_REQUIRE_SLURM:-0}" = 1 ]; then
    echo "FAIL: $* (CDVP_REQUIRE_SLURM=1)"
    exit 1
  fi
  echo "SKIP: $*"
  exit 77
}

for tool in munged slurmctld slurmd sbatch scancel squeue; do
  if ! command -v "$tool" > /dev/null; then
    skip "$tool is not installed (apt-get install slurmctld slurmd slurm-client munge)"
  fi
done
if [ "$(id -u)" -ne 0 ]; then
  skip "the test's Slurm daemons run as root"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/cdvp-slurm-XXXXXX")
cleanup() {
  for daemon in slurmd slurmctld munged; do
    [ -f "$work/$daemon.pid" ] && kill "$(cat "$work/$daemon.pid")" 2> /dev/null || true
  done
  sleep 1
  rm -rf "$work"
}
trap cleanup EXIT
[ -n "${CDVP_SLURM_KEEP:-}" ] && trap - EXIT
fail() {
  echo "FAIL: $*"
  for log in "$work"/log/*.log "$work"/run/results/*.log; do
    [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; }
  done
  exit 1
}

# Ports of this test's own, clear of a real Slurm's 6817/6818.
port=$((20000 + RANDOM % 20000))
mkdir -p "$work/state" "$work/spool" "$work/log" "$work/run"
head -c 1024 /dev/urandom > "$work/munge.key"
chmod 400 "$work/munge.key"
cat > "$work/slurm.conf" <<CONF
ClusterName=cdvptest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=cdvp Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
munged --socket="$work/munge.socket" --key-file="$work/munge.key" --pid-file="$work/munged.pid" \
       --seed-file="$work/munge.seed" --log-file="$work/log/munged.log" -f
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF" -N localhost
for _ in $(seq 60); do
  sinfo -h -o %T 2> /dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o %T | grep -q idle || fail "the test's Slurm node did not come up"

# A grid of 8 points whose points take a moment, in 2 shards of 4.
cd "$work/run"
export CDVP=$cdvp RESULTS=results SHARDS=2
export GRID="--board adm-xrc-ii --set m=1,4 --set objects=500,1000,2000,4000 --frames 600 --baseline sap"
submitted=$("$source_dir/docs/sweep-slurm.sh" --cpus-per-task=1)
echo "$submitted"
array=$(sed -n 's/^sweep: job array \([0-9]*\) .*/\1/p' <<< "$submitted")
merge=$(sed -n 's/.*merge: job \([0-9]*\) .*/\1/p' <<< "$submitted")
[ -n "$array" ] && [ -n "$merge" ] || fail "docs/sweep-slurm.sh printed no job ids: $submitted"
[ -d results ] || fail "docs/sweep-slurm.sh made no results directory"

# Kill task 1 once its first point is in its table, before its last.
rows() { if [ -f "$1" ]; then tail -n +2 "$1" | grep -c . || true; else echo 0; fi; }
killed=no
for _ in $(seq 600); do
  done_rows=$(rows results/shard-1/sweep.csv)
  if [ "$done_rows" -ge 1 ] && [ "$done_rows" -lt 4 ]; then
    scancel "${array}_1"
    killed=yes
    break
  fi
  [ "$done_rows" -ge 4 ] && break
  sleep 0.1
done
[ "$killed" = yes ] || fail "task 1 ran all its points before it could be killed"
# Its merge can no longer start: drop it, and wait for task 2.
scancel "$merge"
sbatch --wait --dependency="afterany:$array" --output=/dev/null --wrap true > /dev/null
kept=$(rows results/shard-1/sweep.csv)
[ "$kept" -lt 4 ] || fail "the killed task kept $kept of its 4 rows"

# Task 1 again, alone: it runs only its missing points, then all is merged.
"$source_dir/docs/sweep-slurm.sh" --cpus-per-task=1 --array=1 --wait > /dev/null ||
  fail "the resubmitted task or its merge failed"
log=$(ls -t results/slurm-*_1.log | head -n 1)
grep -q "($((4 - kept)) run now;" "$log" || fail "the resubmitted task did not run only its $((4 - kept)) missing points: $(tail -n 1 "$log")"
[ -f results/all/sweep.csv ] || fail "the merge wrote no results/all/sweep.csv"

# The same grid swept here: equal rows outside the measured columns.
read -r -a grid <<< "$GRID"
"$cdvp" sweep "${grid[@]}" --no-plots -q --out local
python3 - results/all/sweep.csv local/sweep.csv <<'PY' || fail "the merged rows differ from a local sweep's"
import csv, sys
def measured(c):  # sw/study/sweep_table.cpp's is_measured_column
    baseline_energy = c.endswith(("_energy_j", "_energy_ratio")) and not c.startswith(("mean_", "median_"))
    return (c in ("point_wall_s", "checksum", "load_average_end") or c.startswith(("config.provenance.", "config.budgets."))
            or c.endswith(("_native_ns", "_host_ns", "_speedup")) or baseline_energy or "_timing_" in c)
def rows(path):
    with open(path, newline="") as f:
        return [{k: v for k, v in row.items() if not measured(k)} for row in csv.DictReader(f)]
merged, local = rows(sys.argv[1]), rows(sys.argv[2])
assert len(local) == 8, len(local)
assert all(r["status"] == "ok" for r in merged), [r["status"] for r in merged]
assert merged == local, next((a, b) for a, b in zip(merged, local) if a != b)
PY
echo "PASS: 8 of 8 points through a Slurm job array of 2 tasks and its merge; task 1 killed after $kept points ran the other $((4 - kept))"
