#!/usr/bin/env bash
# Submits `foldkit bench` to SLURM as a job array, one shard per array task, and a merge job
# that starts when every shard has succeeded: OUTDIR/shards/K/ hold the shards, OUTDIR/merged/
# the merged logs, one per scene, OUTDIR/slurm-*.out the job output (docs/BENCHMARKING.md).
#
#   scripts/bench-slurm.sh [--shards N] [--foldkit PATH] [--sbatch "OPTIONS"] [--dry-run] SUITE OUTDIR [foldkit bench options…]
#   e.g. scripts/bench-slurm.sh --shards 64 --sbatch "--partition=short --time=02:00:00" full /scratch/$USER/full --time 10 --runs 100
#
# --shards defaults to 16; --foldkit to the foldkit on PATH (else build/apps/foldkit), given as an
# absolute path because the jobs run elsewhere; --sbatch options go to both sbatch calls (each
# shard needs one CPU: give --time enough for its share of runs × the per-run limit); --dry-run
# prints the sbatch commands instead of submitting. OUTDIR must be on a file system the compute
# nodes share. Options after OUTDIR go to every shard; do not pass --shard or -o there.
set -euo pipefail

usage() { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

shards=16
sbatch_opts=""
dry=0
foldkit=$(command -v foldkit || true)
[ -n "$foldkit" ] || foldkit="$(cd "$(dirname "$0")/.." && pwd)/build/apps/foldkit"
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards=${2:?--shards needs a number}; shift 2 ;;
    --foldkit) foldkit=${2:?--foldkit needs a path}; shift 2 ;;
    --sbatch) sbatch_opts=${2?--sbatch needs options}; shift 2 ;;
    --dry-run) dry=1; shift ;;
    -h|--help) usage ;;
    --*) echo "bench-slurm: unknown option $1 (options for foldkit bench go after SUITE OUTDIR)" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || usage
suite=$1 out=$2
shift 2
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "bench-slurm: --shards must be a positive integer" >&2; exit 2; }
for a in "$@"; do
  case "$a" in --shard|--shard=*|-o|--output|--output=*) echo "bench-slurm: $a is set by this script" >&2; exit 2 ;; esac
done
foldkit=$(realpath -m "$foldkit")
[ "$dry" = 1 ] || [ -x "$foldkit" ] || { echo "bench-slurm: no foldkit executable at '$foldkit' (use --foldkit PATH)" >&2; exit 2; }
mkdir -p "$out/shards"
out=$(realpath "$out")

q() { local s; s=$(printf '%q ' "$@"); printf '%s' "${s% }"; }
# SLURM_ARRAY_TASK_ID is expanded by the job's shell, not here.
shard_cmd="mkdir -p $(q "$out")/shards/\$SLURM_ARRAY_TASK_ID && $(q "$foldkit" bench "$suite") --shard \$SLURM_ARRAY_TASK_ID/$shards -o $(q "$out")/shards/\$SLURM_ARRAY_TASK_ID $(q "$@")"
merge_cmd="$(q "$foldkit") bench-merge $(q "$out")/shards/*/ -o $(q "$out/merged") --json > $(q "$out/merged.json")"

# shellcheck disable=SC2206 # word splitting of the user's sbatch options is intended
extra=($sbatch_opts)
array=(sbatch --parsable --job-name=foldkit-bench --array=1-"$shards" --cpus-per-task=1 --output="$out/slurm-%A_%a.out"
       "${extra[@]}" --wrap="$shard_cmd")
if [ "$dry" = 1 ]; then
  printf '%q ' "${array[@]}"; echo
  printf '%q ' sbatch --parsable --job-name=foldkit-bench-merge --dependency=afterok:JOBID --output="$out/slurm-merge-%j.out" \
    "${extra[@]}" --wrap="$merge_cmd"; echo
  exit 0
fi
command -v sbatch >/dev/null || { echo "bench-slurm: sbatch not found (is this a SLURM login node?)" >&2; exit 2; }
job=$("${array[@]}")
job=${job%%;*}
merge=$(sbatch --parsable --job-name=foldkit-bench-merge --dependency=afterok:"$job" --output="$out/slurm-merge-%j.out" \
  "${extra[@]}" --wrap="$merge_cmd")
echo "bench-slurm: array job $job ($shards shards), merge job ${merge%%;*} -> $out/merged" >&2
echo "bench-slurm: follow with: squeue -j $job,${merge%%;*}" >&2
