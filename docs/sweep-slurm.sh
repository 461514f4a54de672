#!/bin/bash
# A cdvp sweep spread over a Slurm job array, then merged (docs/sweep.md).
#
#   docs/sweep-slurm.sh [sbatch options...]      e.g. --partition=P --account=A
#
# Run where you submit jobs, it makes the results directory (Slurm does not
# make a log's directory), submits itself as a job array whose task K of N
# sweeps shard K/N into RESULTS/shard-K, and a merge into RESULTS/all that
# starts once every task has ended well; it prints both job ids. The sbatch
# options given (partition, account, time, cpus per task, --wait) go to both.
# Set in the environment (exported to the tasks):
#   CDVP     the cdvp binary              (default: cdvp on PATH)
#   RESULTS  shards, logs and the merge   (default: results)
#   SHARDS   array tasks, N               (default: 8)
#   GRID     the axes and run options     (default: the grid below)
# A task that was killed or failed: submit it again alone with the same
# environment, `docs/sweep-slurm.sh --array=K`: it runs only the points its
# shard has not finished, and the merge after it takes every shard again.
#SBATCH --job-name=cdvp-sweep
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
set -euo pipefail

CDVP=${CDVP:-cdvp}
RESULTS=${RESULTS:-results}
SHARDS=${SHARDS:-8}
GRID=${GRID:---board adm-xrc-ii,pcie-gen3-x8 --set m=1,2,4,8,16,24 --set objects=50:2000:x2 --frames 30 --baseline sap,soa}
export CDVP RESULTS SHARDS GRID

if [ -z "${SLURM_ARRAY_TASK_ID:-}" ]; then
  # Submitting: the array, then the merge that waits for all of it.
  mkdir -p "$RESULTS"
  array=$(sbatch --parsable --array="1-$SHARDS" --output="$RESULTS/slurm-%A_%a.log" "$@" "$0")
  array=${array%%;*}
  merge=$(sbatch --parsable --job-name=cdvp-merge --dependency="afterok:$array" \
          --output="$RESULTS/merge-%j.log" "$@" --wrap "\"$CDVP\" merge --out \"$RESULTS/all\" \"$RESULTS\"/shard-*")
  echo "sweep: job array $array ($SHARDS tasks, logs in $RESULTS/); merge: job ${merge%%;*} into $RESULTS/all"
  exit 0
fi

# A task: its shard of the same grid (only --shard and --out differ). The
# summary line in its log says how many points it ran now.
read -r -a grid <<< "$GRID"
exec "$CDVP" sweep "${grid[@]}" --jobs "${SLURM_CPUS_PER_TASK:-1}" --no-plots \
    --shard "$SLURM_ARRAY_TASK_ID/$SHARDS" --out "$RESULTS/shard-$SLURM_ARRAY_TASK_ID"
