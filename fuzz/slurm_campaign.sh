#!/bin/bash
# A `dlab fuzz` campaign as a Slurm job array: task k of n runs shard k/n into
# its own directory; a dependent job merges them into exactly the unsharded
# result (dlab fuzz merge). Usage, from the repository root after building:
#
#   sbatch --array=1-64 fuzz/slurm_campaign.sh OUT_PREFIX [dlab fuzz options...]
#   sbatch --dependency=afterok:<array job id> --wrap \
#     "build/cli/dlab fuzz merge OUT_PREFIX.shard*-of-64 --out OUT_PREFIX.merged"
#
# e.g. sbatch --array=1-64 fuzz/slurm_campaign.sh /scratch/c1 --algo bowyer-watson,lawson \
#        --kernel float,epsilon,adaptive --gen mix --n 10..200 --seed 1 --cases 1000000
#
# Every shard must get the same options (and --cases, not --budget, for an
# exact merge). A preempted or timed-out task resumes where it stopped when
# requeued: the same command continues DIR/results.jsonl. Exit status 1 of a
# task means an exact pair failed in its shard (a bug to look at), 2 bad usage.
#SBATCH --job-name=dlab-fuzz
#SBATCH --cpus-per-task=1
#SBATCH --mem=6G
#SBATCH --time=04:00:00
#SBATCH --requeue
#SBATCH --output=dlab-fuzz-%A_%a.log
set -euo pipefail
if [ $# -lt 1 ] || [ -z "${SLURM_ARRAY_TASK_ID:-}" ] || [ -z "${SLURM_ARRAY_TASK_COUNT:-}" ]; then
  echo "usage: sbatch --array=1-N $0 OUT_PREFIX [dlab fuzz options]" >&2
  exit 2
fi
prefix=$1
shift
k=$SLURM_ARRAY_TASK_ID
n=$SLURM_ARRAY_TASK_COUNT
DLAB=${DLAB:-build/cli/dlab}
exec "$DLAB" fuzz "$@" --jobs "${SLURM_CPUS_PER_TASK:-1}" --shard "$k/$n" --out "$prefix.shard$k-of-$n"
