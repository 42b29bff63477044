#!/usr/bin/env bash
# The README's two commands in either order on one build folder (issue 32), configure only:
# 1. the demo's configure on a machine where pybind11 is not yet installed (hidden here with
#    CMAKE_DISABLE_FIND_PACKAGE_pybind11, then uncovered again, as installing it would), then the
#    test command's: the Python tests must be registered;
# 2. the demo's configure after the test command's: the folder keeps its Python and browser
#    tests (the demo does not switch them off).
# Each check is scripts/check-parts.sh; the folder is a temporary one, removed on exit.
set -euo pipefail
cd "$(dirname "$0")/.."
build="$(mktemp -d "${TMPDIR:-/tmp}/foldkit-order.XXXXXX")"
trap 'rm -rf "$build"' EXIT
fail() { echo "test-script-order: $*" >&2; exit 1; }

bash scripts/configure.sh cli "$build" -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON >/dev/null 2>&1 ||
  fail "the demo's configure failed"
grep -q '^FOLDKIT_BUILD_PYTHON:BOOL=OFF' "$build/CMakeCache.txt" || fail "the demo's configure did not leave Python off"
# pybind11 installed after the demo: the cache still says OFF, as it did on a new user's machine.
cmake -U CMAKE_DISABLE_FIND_PACKAGE_pybind11 -S . -B "$build" >/dev/null 2>&1 || fail "reconfiguring with pybind11 failed"
grep -q '^FOLDKIT_BUILD_PYTHON:BOOL=OFF' "$build/CMakeCache.txt" || fail "the reconfigure switched Python on by itself"
bash scripts/configure.sh all "$build" >/dev/null 2>&1 || fail "the test command's configure failed after the demo's"
bash scripts/check-parts.sh "$build" || fail "demo then tests: a part is missing"
echo "test-script-order: demo then tests: Python and browser tests registered" >&2

bash scripts/configure.sh cli "$build" >/dev/null 2>&1 || fail "the demo's configure failed after the test command's"
bash scripts/check-parts.sh "$build" || fail "tests then demo: the demo's configure dropped a part"
grep -q '^FOLDKIT_BUILD_TESTS:BOOL=ON' "$build/CMakeCache.txt" || fail "tests then demo: the demo switched the tests off"
echo "test-script-order: tests then demo: the folder keeps every part" >&2
