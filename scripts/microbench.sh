#!/usr/bin/env bash
# Runs every Google Benchmark program (microbench/bench_*) with JSON output, then pairs each of
# our entries with its baseline and prints the ratios (scripts/bench_ratios.py).
#
#   bash scripts/microbench.sh [--long] [--build-dir DIR] [--out DIR] [--only NAME] [-- ARGS...]
#
#   --long         0.5 s per benchmark instead of 0.05 s, and the slowest baselines too (hybrd on
#                  500 modules alone takes about a minute); the default run takes a few minutes
#                  on two cores
#   --build-dir    the CMake build folder (default: build); configured (Release) and the benchmark
#                  targets built when needed
#   --out          where NAME.json, ratios.csv and ratios.md go (default: BUILD/microbench)
#   --only NAME    run just this program (e.g. bench_fk); repeatable
#   ARGS           passed to every program (e.g. --benchmark_repetitions=3)
# JOBS (environment) sets the build's parallelism (default: nproc).
set -euo pipefail
cd "$(dirname "$0")/.."

build=build
out=
long=0
only=()
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --long) long=1 ;;
    --build-dir) build="${2:?--build-dir needs a folder}"; shift ;;
    --out) out="${2:?--out needs a folder}"; shift ;;
    --only) only+=("${2:?--only needs a program name}"); shift ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "microbench.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
out="${out:-$build/microbench}"

programs=(bench_fk bench_closure bench_projection bench_constraint_projection bench_simulation bench_stiffness bench_hamiltonian bench_pattern bench_dynamics)
if [ ${#only[@]} -gt 0 ]; then programs=("${only[@]}"); fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DFOLDKIT_BUILD_BENCHMARKS=ON >&2
elif grep -q '^FOLDKIT_BUILD_BENCHMARKS:BOOL=OFF' "$build/CMakeCache.txt"; then
  cmake -S . -B "$build" -DFOLDKIT_BUILD_BENCHMARKS=ON >&2
fi
if grep -q '^CMAKE_BUILD_TYPE:STRING=Debug' "$build/CMakeCache.txt"; then
  echo "microbench.sh: warning: $build is a Debug build; the ratios will not mean much" >&2
fi
cmake --build "$build" -j "${JOBS:-$(nproc)}" --target "${programs[@]}" >&2

if [ "$long" = 1 ]; then min_time=0.5; else min_time=0.05; fi
# Quick runs leave out the baselines that take minutes on their own.
quick_filter() {
  case "$1" in
    bench_stiffness) echo "-BM_Stiffness_Baseline/500" ;;
    *) echo "" ;;
  esac
}

mkdir -p "$out"
start=$(date +%s)
for name in "${programs[@]}"; do
  exe="$build/microbench/$name"
  [ -x "$exe" ] || { echo "microbench.sh: $exe was not built" >&2; exit 1; }
  args=(--benchmark_min_time="$min_time" --benchmark_format=json --benchmark_out_format=json
        --benchmark_out="$out/$name.json")
  filter=$(quick_filter "$name")
  if [ "$long" = 0 ] && [ -n "$filter" ]; then args+=(--benchmark_filter="$filter"); fi
  echo "== $name" >&2
  t0=$(date +%s)
  # JSON goes to the file; the console copy on stdout is not needed.
  "$exe" "${args[@]}" "${extra[@]}" > /dev/null
  echo "   $(( $(date +%s) - t0 )) s" >&2
done
echo "all programs: $(( $(date +%s) - start )) s; JSON in $out" >&2

python3 scripts/bench_ratios.py "$out" --csv "$out/ratios.csv"
python3 scripts/bench_ratios.py "$out" --markdown > "$out/ratios.md" 2> /dev/null
echo "ratios: $out/ratios.csv, $out/ratios.md" >&2
