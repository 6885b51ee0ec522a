#!/bin/bash
# A `dlab study` as a Slurm job array: task k of n runs shard k/n into its own
# directory; a dependent job merges them into exactly the unsharded runs.csv
# (measured columns aside: they come from the machines that ran them).
# Usage, from the repository root after building:
#
#   sbatch --array=1-16 studies/slurm_study.sh CONFIG.json OUT_PREFIX
#   sbatch --dependency=afterok:<array job id> --wrap \
#     "build/cli/dlab study merge OUT_PREFIX.shard*-of-16 --out OUT_PREFIX"
#
# e.g. sbatch --array=1-16 studies/slurm_study.sh studies/configs/default.json /scratch/default
#
# Every task must get the same CONFIG. A preempted or timed-out task resumes
# where it stopped when requeued: the same command keeps the rows already in
# its directory. Ask for whole cores (--cpus-per-task) and keep --jobs at or
# below them, or the timings measure the contention. Exit status 1 of a task:
# an exact pair failed in its shard (a bug to look at); 2: bad config or usage.
#SBATCH --job-name=dlab-study
#SBATCH --cpus-per-task=1
#SBATCH --mem=6G
#SBATCH --time=04:00:00
#SBATCH --requeue
#SBATCH --output=dlab-study-%A_%a.log
set -euo pipefail
if [ $# -ne 2 ] || [ -z "${SLURM_ARRAY_TASK_ID:-}" ] || [ -z "${SLURM_ARRAY_TASK_COUNT:-}" ]; then
  echo "usage: sbatch --array=1-N $0 CONFIG.json OUT_PREFIX" >&2
  exit 2
fi
config=$1
prefix=$2
k=$SLURM_ARRAY_TASK_ID
n=$SLURM_ARRAY_TASK_COUNT
DLAB=${DLAB:-build/cli/dlab}
exec "$DLAB" study "$config" --jobs "${SLURM_CPUS_PER_TASK:-1}" --shard "$k/$n" --out "$prefix.shard$k-of-$n"
