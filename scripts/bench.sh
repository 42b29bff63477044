#!/usr/bin/env bash
# Builds and runs the Google Benchmark programs; JSON results go to ./build/bench-results.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p build/bench-results
for b in build/benchmarks/bench_*; do
  [ -x "$b" ] || continue
  name=$(basename "$b")
  "$b" --benchmark_out="build/bench-results/$name.json" --benchmark_out_format=json "$@"
done
