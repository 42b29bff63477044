#!/usr/bin/env bash
# CI: runs scripts/bench-slurm.sh for real on a one-node SLURM cluster on localhost
# (scripts/slurm-local.sh; needs root or sudo, installs munge and SLURM when missing):
#   1. the quick suite as a job array of 4 shards plus the merge job, waited for with a bound;
#      the merged logs, loaded with ompl_benchmark_statistics, hold the same (scene, planner, run)
#      set as an unsharded `foldkit bench` of the same suite, each run once;
#   2. an array task that fails on purpose (a --foldkit wrapper exiting 1 in task 2): the script
#      exits 1 and names that task (and no other) and its output file, and the merge job never runs;
#   3. a task that outlives --wait: the script exits 124 and cancels the jobs.
# Uses build/apps/foldkit (build it first: scripts/build.sh). The cluster is stopped on exit,
# unless it was running before. About 25 s once the packages are installed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
foldkit=$root/build/apps/foldkit

failure=""
fail() { failure=$*; echo "test-slurm: FAILED: $*" >&2; exit 1; }
[ -x "$foldkit" ] || fail "no $foldkit (build first: scripts/build.sh)"
command -v ompl_benchmark_statistics >/dev/null || fail "ompl_benchmark_statistics not found (Debian package ompl-demos; scripts/install-deps.sh)"

work=$(mktemp -d /tmp/foldkit-test-slurm.XXXXXX)
was_running=0
bash scripts/slurm-local.sh status >/dev/null 2>&1 && was_running=1
cleanup() {
  local rc=$?
  if [ "$rc" -ne 0 ]; then
    echo "test-slurm: cluster state at failure:" >&2
    bash scripts/slurm-local.sh status >&2 || true
    for f in "${FOLDKIT_SLURM_DIR:-/tmp/foldkit-slurm}"/slurm{ctld,d}.log; do
      [ -r "$f" ] || continue
      echo "--- last lines of $f" >&2
      tail -n 15 "$f" >&2
    done
    echo "test-slurm: outputs kept in $work" >&2
    [ -z "$failure" ] || echo "test-slurm: FAILED: $failure" >&2  # again, below the logs
  else
    rm -rf "$work"
  fi
  [ "$was_running" = 1 ] || bash scripts/slurm-local.sh stop || true
  exit "$rc"
}
trap cleanup EXIT

t0=$SECONDS
env_line=$(bash scripts/slurm-local.sh start) || fail "scripts/slurm-local.sh start failed"
eval "$env_line"  # export SLURM_CONF=...
[ -r "${SLURM_CONF:-}" ] || fail "scripts/slurm-local.sh start printed no readable SLURM_CONF"
echo "test-slurm: cluster up after $((SECONDS - t0)) s (SLURM_CONF=$SLURM_CONF)" >&2
sinfo >&2

suite=quick
bench_opts=(--runs 5 --time 1)
shards=4

# (scene, planner, run index) of every run in the logs of a folder, one per line, sorted.
runs_of() {
  local dir=$1 db=$2
  ompl_benchmark_statistics -d "$db" "$dir"/*.log >/dev/null 2>"$db.stderr" \
    || { cat "$db.stderr" >&2; fail "ompl_benchmark_statistics could not load $dir/*.log"; }
  python3 - "$db" <<'EOF'
import sqlite3, sys
c = sqlite3.connect(sys.argv[1])
for row in sorted(c.execute(
        "select e.scene, p.name, r.run_index from runs r join experiments e on r.experimentid = e.id "
        "join plannerConfigs p on r.plannerid = p.id")):
    print(*row, sep="\t")
EOF
}

# 1. The real job array, compared with an unsharded run.
echo "test-slurm: 1. $suite suite, $shards shards, ${bench_opts[*]}" >&2
bash scripts/bench-slurm.sh --shards "$shards" --foldkit "$foldkit" --wait 120 "$suite" "$work/array" "${bench_opts[@]}" \
  || fail "bench-slurm.sh exited $? on the $suite suite"
for k in $(seq "$shards"); do
  ls "$work"/array/shards/"$k"/*.log >/dev/null 2>&1 || fail "shard $k wrote no log in $work/array/shards/$k"
done
[ -s "$work/array/merged.json" ] || fail "the merge job wrote no $work/array/merged.json"
"$foldkit" bench "$suite" "${bench_opts[@]}" -o "$work/plain" 2>"$work/plain.stderr" \
  || { cat "$work/plain.stderr" >&2; fail "unsharded foldkit bench failed"; }
runs_of "$work/array/merged" "$work/merged.db" >"$work/merged.runs"
runs_of "$work/plain" "$work/plain.db" >"$work/plain.runs"
expected=$(( $(wc -l <"$work/plain.runs") ))
[ "$expected" -gt 0 ] || fail "the unsharded run loaded no runs"
[ "$(sort -u "$work/merged.runs" | wc -l)" -eq "$(wc -l <"$work/merged.runs")" ] \
  || fail "a (scene, planner, run) appears twice in the merged logs: $(sort "$work/merged.runs" | uniq -d | head -n 3 | tr '\t\n' ' ;')"
diff <(sort -u "$work/plain.runs") <(sort -u "$work/merged.runs") >"$work/runs.diff" \
  || { cat "$work/runs.diff" >&2; fail "merged (scene, planner, run) set differs from the unsharded run's (< unsharded, > merged)"; }
echo "test-slurm: 1. ok: $expected runs merged from $shards shards, the same (scene, planner, run) set as unsharded" >&2

# 2. A failing array task: exit 1, the task and its output file named, no merge.
echo "test-slurm: 2. array task 2 fails on purpose" >&2
cat >"$work/foldkit-fails-task-2" <<EOF
#!/bin/sh
if [ "\$SLURM_ARRAY_TASK_ID" = 2 ]; then echo "foldkit-fails-task-2: failing on purpose" >&2; exit 1; fi
exec $(printf '%q' "$foldkit") "\$@"
EOF
chmod +x "$work/foldkit-fails-task-2"
set +e
bash scripts/bench-slurm.sh --shards 3 --foldkit "$work/foldkit-fails-task-2" --wait 60 "$suite" "$work/fail" \
  2>"$work/fail.stderr"  # no bench options: the defaults (an empty one once made every task fail)
rc=$?
set -e
cat "$work/fail.stderr" >&2
[ "$rc" -eq 1 ] || fail "bench-slurm.sh exited $rc with a failing array task, not 1"
job=$(sed -n 's/^bench-slurm: array job \([0-9]*\) .*/\1/p' "$work/fail.stderr")
[ -n "$job" ] || fail "no array job ID in bench-slurm.sh's output"
out="$work/fail/slurm-${job}_2.out"
grep -qF "array task ${job}_2 " "$work/fail.stderr" || fail "the message does not name array task ${job}_2"
grep -qF "$out" "$work/fail.stderr" || fail "the message does not name the output file $out"
grep -q "failing on purpose" "$out" || fail "$out does not hold the task's output"
if grep -qE "array task ${job}_(1|3) " "$work/fail.stderr"; then fail "a task that completed was reported as failed"; fi
[ ! -e "$work/fail/merged" ] || fail "the merge job ran although a task failed"
echo "test-slurm: 2. ok: exit 1, task ${job}_2 and $out named" >&2

# 3. The bound: a task that sleeps past --wait is cancelled, exit 124.
echo "test-slurm: 3. a task outlives --wait 3" >&2
printf '#!/bin/sh\nsleep 120\n' >"$work/foldkit-sleeps"
chmod +x "$work/foldkit-sleeps"
set +e
bash scripts/bench-slurm.sh --shards 1 --foldkit "$work/foldkit-sleeps" --wait 3 "$suite" "$work/slow" 2>"$work/slow.stderr"
rc=$?
set -e
cat "$work/slow.stderr" >&2
[ "$rc" -eq 124 ] || fail "bench-slurm.sh exited $rc past its --wait bound, not 124"
jobs=$(sed -n 's/^bench-slurm: array job \([0-9]*\) .*, merge job \([0-9]*\) .*/\1,\2/p' "$work/slow.stderr")
[ -n "$jobs" ] || fail "no job IDs in bench-slurm.sh's output"
left=""
for _ in $(seq 20); do
  left=$(squeue -h -j "$jobs" -t PENDING,RUNNING,COMPLETING -o %i 2>/dev/null || true)
  [ -z "$left" ] && break
  sleep 0.5
done
[ -z "$left" ] || fail "jobs left after the timeout: $left"
echo "test-slurm: 3. ok: exit 124, jobs cancelled" >&2

echo "test-slurm: all checks passed in $((SECONDS - t0)) s" >&2
