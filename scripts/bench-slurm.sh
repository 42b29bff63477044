#!/usr/bin/env bash
# Submits `foldkit bench` to SLURM as a job array, one shard per array task, and a merge job
# that starts when every shard has succeeded: OUTDIR/shards/K/ hold the shards, OUTDIR/merged/
# the merged logs, one per scene, OUTDIR/slurm-*.out the job output (docs/BENCHMARKING.md).
#
#   scripts/bench-slurm.sh [--shards N] [--foldkit PATH] [--sbatch "OPTIONS"] [--wait [SECONDS]] [--dry-run] SUITE OUTDIR [foldkit bench options…]
#   e.g. scripts/bench-slurm.sh --shards 64 --sbatch "--partition=short --time=02:00:00" full /scratch/$USER/full --time 10 --runs 100
#
# --shards defaults to 16; --foldkit to the foldkit on PATH (else build/apps/foldkit), given as an
# absolute path because the jobs run elsewhere; --sbatch options go to both sbatch calls (each
# shard needs one CPU: give --time enough for its share of runs × the per-run limit); --dry-run
# prints the sbatch commands instead of submitting. OUTDIR must be on a file system the compute
# nodes share. Options after OUTDIR go to every shard; do not pass --shard or -o there.
# --wait stays until the array and the merge job have ended, at most SECONDS (default 86400),
# watching them with squeue: exit 0 when the merge job completed; exit 1 when an array task or
# the merge failed (each failed task is named with its output file, the merge job cancelled);
# exit 124 when the bound passed (the jobs left are cancelled). Without --wait it returns at once.
set -euo pipefail

usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

shards=16
sbatch_opts=""
dry=0
wait_s=""
foldkit=$(command -v foldkit || true)
[ -n "$foldkit" ] || foldkit="$(cd "$(dirname "$0")/.." && pwd)/build/apps/foldkit"
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards=${2:?--shards needs a number}; shift 2 ;;
    --foldkit) foldkit=${2:?--foldkit needs a path}; shift 2 ;;
    --sbatch) sbatch_opts=${2?--sbatch needs options}; shift 2 ;;
    --dry-run) dry=1; shift ;;
    --wait)
      if [[ "${2:-}" =~ ^[0-9]+$ ]]; then wait_s=$2; shift 2; else wait_s=86400; shift; fi
      [ "$wait_s" -gt 0 ] || { echo "bench-slurm: --wait needs a positive number of seconds" >&2; exit 2; } ;;
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
  case "$a" in
    --shard|--shard=*|-o|--output|--output=*) echo "bench-slurm: $a is set by this script" >&2; exit 2 ;;
    --shards|--foldkit|--sbatch|--wait|--dry-run) echo "bench-slurm: $a goes before SUITE OUTDIR (after them, options go to foldkit bench)" >&2; exit 2 ;;
  esac
done
foldkit=$(realpath -m "$foldkit")
[ "$dry" = 1 ] || [ -x "$foldkit" ] || { echo "bench-slurm: no foldkit executable at '$foldkit' (use --foldkit PATH)" >&2; exit 2; }
mkdir -p "$out/shards"
out=$(realpath "$out")

q() { [ $# -gt 0 ] || return 0; local s; s=$(printf '%q ' "$@"); printf '%s' "${s% }"; }
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
merge=${merge%%;*}
echo "bench-slurm: array job $job ($shards shards), merge job $merge -> $out/merged" >&2
if [ -z "$wait_s" ]; then
  echo "bench-slurm: follow with: squeue -j $job,$merge" >&2
  exit 0
fi

# --wait: poll squeue (every job state, one line per array task) until every task and the merge
# job have ended. A job leaves squeue MinJobAge (default 300 s) after it ended; a state missed so
# is looked up in the jobcomp/filetxt log when the cluster writes one (sacct needs slurmdbd).
final_ok=COMPLETED
final_bad=" FAILED CANCELLED TIMEOUT NODE_FAIL OUT_OF_MEMORY BOOT_FAIL DEADLINE PREEMPTED SPECIAL_EXIT REVOKED "
declare -A state      # array task ID -> last state seen
merge_state="" merge_reason=""
jobcomp=""
config=$(scontrol show config 2>/dev/null || true)  # not piped into grep -q: SIGPIPE under pipefail
if [[ "$config" =~ JobCompType\ *=\ *jobcomp/filetxt ]]; then
  jobcomp=$(sed -n 's/^JobCompLoc *= *//p' <<<"$config")
fi
# jobcomp_field RECORD-PATTERN FIELD: FIELD of the last jobcomp record matching the pattern.
jobcomp_field() {
  [ -n "$jobcomp" ] && [ -r "$jobcomp" ] || return 0
  grep -E "$1" "$jobcomp" 2>/dev/null | tail -n 1 | tr ' ' '\n' | sed -n "s/^$2=//p"
}
task_out() { echo "$out/slurm-${job}_$1.out"; }
exit_code() {  # exit code of array task $1 (status:signal), when SLURM still knows it
  local c
  c=$(scontrol show job -o "${job}_$1" 2>/dev/null | tr ' ' '\n' | sed -n 's/^ExitCode=//p' | head -n 1)
  [ -n "$c" ] || c=$(jobcomp_field "ArrayJobId=$job ArrayTaskId=$1 " ExitCode)
  echo "${c:-unknown}"
}
is_final() { [ "$1" = "$final_ok" ] || [[ "$final_bad" == *" $1 "* ]] || [ "$1" = GONE ]; }
interrupted() {
  echo "bench-slurm: interrupted; the jobs stay queued (cancel with: scancel $job $merge)" >&2
  exit 130
}
trap interrupted INT TERM

start=$SECONDS last="" poll=2
while :; do
  if lines=$(squeue -h -r -t all -j "$job,$merge" -o '%i|%T|%r' 2>&1); then
    seen=" " merge_seen=0
    while IFS='|' read -r id st reason; do
      case "$id" in
        "$merge") merge_state=$st merge_reason=$reason merge_seen=1 ;;
        "${job}_"*) k=${id#"${job}_"}; [[ "$k" =~ ^[0-9]+$ ]] && { state[$k]=$st; seen+="$k "; } ;;
      esac
    done <<<"$lines"
    [ "$merge_seen" = 1 ] || [ -z "$merge_state" ] || is_final "$merge_state" || merge_state=GONE
  elif [[ "$lines" == *"Invalid job id"* ]]; then
    seen=" "  # both jobs left the queue
    [ -z "$merge_state" ] || is_final "$merge_state" || merge_state=GONE
  else
    echo "bench-slurm: squeue failed (retrying): $lines" >&2
    if [ $((SECONDS - start)) -lt "$wait_s" ]; then
      sleep "$poll"
      continue
    fi
    seen=""  # past the bound: the states last seen, then the timeout below
  fi
  # Tasks that left the queue before this script saw them end: their jobcomp record, else unknown.
  for k in "${!state[@]}"; do
    if [ -n "$seen" ] && [[ "$seen" != *" $k "* ]] && ! is_final "${state[$k]}"; then
      st=$(jobcomp_field "ArrayJobId=$job ArrayTaskId=$k " JobState)
      state[$k]=${st:-GONE}
    fi
  done
  if [ "$merge_state" = GONE ]; then
    st=$(jobcomp_field "^JobId=$merge " JobState)
    merge_state=${st:-GONE}
  fi
  # Progress: counts per state, printed when they change.
  declare -A count=()
  n_final=0 failed=() unknown=()
  for k in $(seq "$shards"); do
    st=${state[$k]:-PENDING}
    count[$st]=$(( ${count[$st]:-0} + 1 ))
    if is_final "$st"; then
      n_final=$((n_final + 1))
      case "$st" in "$final_ok") ;; GONE) unknown+=("$k") ;; *) failed+=("$k") ;; esac
    fi
  done
  summary=""
  for st in $(printf '%s\n' "${!count[@]}" | sort); do summary+="${count[$st]} ${st,,}, "; done
  summary="shards: ${summary%, }; merge: ${merge_state:-PENDING}${merge_reason:+ ($merge_reason)}"
  summary=${summary% (None)}
  [ "$summary" = "$last" ] || echo "bench-slurm: [$((SECONDS - start)) s] $summary" >&2
  last=$summary

  if [ "$merge_state" = GONE ] && [ -s "$out/merged.json" ]; then
    # Left the queue unseen, but only a merge that succeeded writes its JSON summary.
    echo "bench-slurm: merge job $merge left the queue unseen; $out/merged.json is written: taking it as completed" >&2
    merge_state=$final_ok
  fi
  if [ "$merge_state" = "$final_ok" ]; then  # afterok: every task completed
    echo "bench-slurm: done in $((SECONDS - start)) s: $shards shards merged into $out/merged ($out/merged.json)" >&2
    exit 0
  fi
  # Tasks in an unknown state fail the run only once SLURM says the merge can never start.
  if [ "$n_final" -eq "$shards" ] && { [ ${#failed[@]} -gt 0 ] || { [ ${#unknown[@]} -gt 0 ] &&
       { [ "$merge_reason" = DependencyNeverSatisfied ] || is_final "${merge_state:-PENDING}"; }; }; }; then
    failed+=("${unknown[@]}")
    echo "bench-slurm: FAILED: ${#failed[@]} of $shards array tasks of job $job did not complete:" >&2
    for k in "${failed[@]}"; do
      echo "bench-slurm: array task ${job}_$k (shard $k/$shards) ${state[$k]/GONE/left the queue in an unknown state}, exit code $(exit_code "$k"), output: $(task_out "$k")" >&2
      [ -r "$(task_out "$k")" ] && tail -n 5 "$(task_out "$k")" | sed 's/^/    /' >&2
    done
    if ! is_final "${merge_state:-PENDING}"; then
      scancel "$merge" 2>/dev/null || true
      echo "bench-slurm: cancelled merge job $merge (its dependency afterok:$job cannot be met)" >&2
    fi
    echo "bench-slurm: the completed shards are in $out/shards/; rerun the failed ones there, then foldkit bench-merge" >&2
    exit 1
  fi
  if is_final "${merge_state:-PENDING}"; then
    echo "bench-slurm: FAILED: merge job $merge ${merge_state/GONE/left the queue in an unknown state}, output: $out/slurm-merge-$merge.out" >&2
    [ -r "$out/slurm-merge-$merge.out" ] && tail -n 5 "$out/slurm-merge-$merge.out" | sed 's/^/    /' >&2
    exit 1
  fi
  if [ $((SECONDS - start)) -ge "$wait_s" ]; then
    echo "bench-slurm: TIMEOUT: the jobs did not end within $wait_s s; cancelling array job $job and merge job $merge" >&2
    for k in $(seq "$shards"); do
      st=${state[$k]:-PENDING}
      [ "$st" = "$final_ok" ] || echo "bench-slurm: array task ${job}_$k (shard $k/$shards) $st, output: $(task_out "$k")" >&2
    done
    scancel "$job" "$merge" 2>/dev/null || true
    exit 124
  fi
  elapsed=$((SECONDS - start))
  poll=$(( elapsed < 60 ? 2 : elapsed < 600 ? 5 : 15 ))
  sleep "$(( poll < wait_s - elapsed ? poll : wait_s - elapsed ))"
done
