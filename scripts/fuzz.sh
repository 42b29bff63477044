#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) in ./build-fuzz and runs one of them.
#   bash scripts/fuzz.sh pmml|cmml|fold|svg|cp|opx|loadcase|cli [SECONDS=600] [JOBS=1]
# The corpus grows in ./build-fuzz/corpus-NAME, seeded from the examples, the shared fixtures
# and the bad-input corpus; crashes are written to ./build-fuzz/crash-NAME-*.
set -euo pipefail
cd "$(dirname "$0")/.."
name=${1:?usage: fuzz.sh pmml|cmml|fold|svg|cp|opx|loadcase|cli [seconds] [jobs]}
seconds=${2:-600}
jobs=${3:-1}
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ is needed (apt-get install clang)" >&2; exit 1; }
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DFOLDKIT_BUILD_FUZZERS=ON \
  -DFOLDKIT_BUILD_TESTS=OFF -DFOLDKIT_BUILD_BENCHMARKS=OFF -DCMAKE_CXX_FLAGS="$flags" >&2
corpus=build-fuzz/corpus-$name
cmake --build build-fuzz -j "$(nproc)" --target "fuzz_$name" >&2
if [ ! -d "$corpus" ]; then
  cmake --build build-fuzz -j "$(nproc)" --target foldkit >&2  # for the seeds
  mkdir -p "$corpus"
  ./build-fuzz/apps/foldkit demo -o build-fuzz/seeds >/dev/null 2>&1
  cp build-fuzz/seeds/*."$name" test/data/bad/*."$name" "$corpus"/ 2>/dev/null || true
  cp ../shared/fixtures/fold/*."$name" ../shared/fixtures/svg/*."$name" test/data/good/*."$name" "$corpus"/ 2>/dev/null || true
  # .cp seeds: a square with its diagonals, and one with a crease past the border.
  if [ "$name" = cp ]; then
    printf '1 0 0 10 0\n1 10 0 10 10\n1 10 10 0 10\n1 0 10 0 0\n2 0 0 10 10\n3 10 0 0 10\n' > "$corpus/square.cp"
    printf '1 0 0 4 0\n1 4 0 4 4\n1 4 4 0 4\n1 0 4 0 0\n2 2 -1 2 5\n0 0 2 4 2\n' > "$corpus/past.cp"
  fi
  # Command lines: every verb's --help, and the README's examples, NUL-separated.
  if [ "$name" = cli ]; then
    for verb in validate info generate convert dof project simulate plan fold stiffness demo hamiltonian carpenter bench bench-merge; do
      printf '%s\000--help' "$verb" > "$corpus/help-$verb"
    done
    printf 'generate\000miura\000--rows\000040\000--cols\000040\000-o\000miura.pmml' > "$corpus/generate"
    printf 'simulate\000a.pmml\000b.cmml\000--json\000--model\000spring\000--frames\000t.fold' > "$corpus/simulate"
    printf 'plan\000a.pmml\000--goal\000g.cmml\000--planner\000RRTConnect\000--time\000001\000--seed\000003\000-o\000p.cmml' > "$corpus/plan"
  fi
fi
parallel=()
# With -jobs, libFuzzer forks workers that log to ./fuzz-N.log: give each target its own folder.
[ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
mkdir -p "build-fuzz/logs-$name"
cd "build-fuzz/logs-$name"
../test/fuzz/"fuzz_$name" "../corpus-$name" -max_total_time="$seconds" "${parallel[@]}" \
  -max_len=65536 -timeout=10 -rss_limit_mb=4096 -artifact_prefix="../crash-$name-" -print_final_stats=1
