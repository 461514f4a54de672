#!/bin/bash
# A cdvp sweep spread over a Slurm job array: task K of N runs shard K/N into
# its own directory. Submit, then merge once every task has finished:
#
#   jobid=$(sbatch --parsable docs/sweep-slurm.sh)
#   sbatch --dependency=afterok:$jobid --wrap "cdvp merge --out results/all results/shard-*"
#
# Each shard is resumable: resubmitting a failed task (sbatch --array=K ...)
# runs only the points it had not finished.
#SBATCH --job-name=cdvp-sweep
#SBATCH --array=1-8
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
#SBATCH --output=results/slurm-%A_%a.log
set -euo pipefail

CDVP=${CDVP:-cdvp}
SHARDS=${SLURM_ARRAY_TASK_COUNT:-8}
K=${SLURM_ARRAY_TASK_ID:?run this as a Slurm job array (sbatch docs/sweep-slurm.sh)}

# The same grid in every task; only --shard and --out differ.
"$CDVP" sweep --board adm-xrc-ii,pcie-gen3-x8 --set m=1,2,4,8,16,24 --set objects=50:2000:x2 \
    --frames 30 --baseline sap,soa \
    --jobs "${SLURM_CPUS_PER_TASK:-1}" --no-plots -q \
    --shard "$K/$SHARDS" --out "results/shard-$K"
