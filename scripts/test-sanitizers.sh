#!/usr/bin/env bash
# Builds the whole project with AddressSanitizer + UndefinedBehaviorSanitizer in ./build-sanitize
# and runs every test there; any report fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Debug keeps assertions (Eigen's included); -O1 keeps the planners' and simulator's timed tests
# within their limits under the sanitizers' slowdown.
# Eigen stops trusting malloc's 16-byte alignment under ASan and switches to offset allocations;
# the prebuilt libompl.so keeps plain malloc, and with both in one process their inline Eigen
# allocators mix (a "bad free" inside OMPL). ASan's malloc is 16-byte aligned on x86-64, so tell
# Eigen so, as in the uninstrumented build (Eigen asserts it in this Debug build).
flags="-O1 -DEIGEN_MALLOC_ALREADY_ALIGNED=1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
# The Python module is left out: an ASan-instrumented extension only loads with the runtime
# preloaded into the interpreter; its suite runs in the Release build.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DFOLDKIT_BUILD_BENCHMARKS=OFF -DFOLDKIT_BUILD_PYTHON=OFF -DFOLDKIT_BUILD_WEB=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >&2
cmake --build build-sanitize -j "$(nproc)" >&2
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Leaks inside libraries foldkit does not build, each with its reason there.
export LSAN_OPTIONS=suppressions=$PWD/scripts/lsan.supp
# Planning tests' time limits ×10 (test/support/test_time.hpp): the search keeps to its limit, and
# the instrumented build is about ten times slower.
export FOLDKIT_TEST_TIME_SCALE=10
# Label scale (AtScale.*, test/folding/at_scale_test.cpp): folds and replays of sheets with
# thousands of facets, minutes under the sanitizers and the same code as the small cases; the
# Release suite runs them.
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" -LE scale

