#!/usr/bin/env bash
# Runs `foldkit bench` as N shards on this machine with GNU parallel (xargs -P when parallel is
# not installed), then merges the shard logs: OUTDIR/shards/K/ hold the shards, OUTDIR/merged/ the
# merged logs, one per scene (docs/BENCHMARKING.md).
#
#   scripts/bench-parallel.sh [--shards N] [--jobs J] [--foldkit PATH] SUITE OUTDIR [foldkit bench options…]
#   e.g. scripts/bench-parallel.sh --shards 8 --jobs 4 full out/full --time 10 --runs 50
#
# --shards defaults to the number of CPUs, --jobs to --shards; --foldkit to the foldkit on PATH
# (else build/apps/foldkit). Options after OUTDIR go to every shard (--time, --runs, --seed,
# --planners, --scenes); do not pass --shard or -o there.
set -euo pipefail

usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

shards=$(nproc 2>/dev/null || echo 2)
jobs=""
foldkit=$(command -v foldkit || true)
[ -n "$foldkit" ] || foldkit="$(cd "$(dirname "$0")/.." && pwd)/build/apps/foldkit"
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards=${2:?--shards needs a number}; shift 2 ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift 2 ;;
    --foldkit) foldkit=${2:?--foldkit needs a path}; shift 2 ;;
    -h|--help) usage ;;
    --*) echo "bench-parallel: unknown option $1 (options for foldkit bench go after SUITE OUTDIR)" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || usage
suite=$1 out=$2
shift 2
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "bench-parallel: --shards must be a positive integer" >&2; exit 2; }
jobs=${jobs:-$shards}
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "bench-parallel: --jobs must be a positive integer" >&2; exit 2; }
[ -x "$foldkit" ] || { echo "bench-parallel: no foldkit executable at '$foldkit' (use --foldkit PATH)" >&2; exit 2; }
for a in "$@"; do
  case "$a" in --shard|--shard=*|-o|--output|--output=*) echo "bench-parallel: $a is set by this script" >&2; exit 2 ;; esac
done

mkdir -p "$out/shards"
echo "bench-parallel: $suite in $shards shards, $jobs at a time, into $out" >&2
# One shard: its own folder and its own stderr file (progress lines), so shards do not interleave.
run_shard() {
  local k=$1
  mkdir -p "$out/shards/$k"
  "$foldkit" bench "$suite" --shard "$k/$shards" -o "$out/shards/$k" "${extra[@]}" 2>"$out/shards/$k/stderr.txt" \
    && echo "shard $k/$shards done" >&2 \
    || { echo "shard $k/$shards failed, see $out/shards/$k/stderr.txt" >&2; return 1; }
}
export -f run_shard
export foldkit suite shards out
extra=("$@")
# Arrays do not cross `export`: hand the options over as one quoted string.
extra_q=$(printf '%q ' "$@")
export extra_q
if command -v parallel >/dev/null; then
  seq 1 "$shards" | parallel --will-cite --halt now,fail=1 --jobs "$jobs" \
    'eval "extra=($extra_q)"; run_shard {}'
else
  seq 1 "$shards" | xargs -P "$jobs" -I{} bash -c 'eval "extra=($extra_q)"; run_shard {}'
fi
"$foldkit" bench-merge "$out"/shards/*/ -o "$out/merged"
echo "bench-parallel: merged logs in $out/merged (ompl_benchmark_statistics -d bench.db $out/merged/*.log)" >&2
