#!/usr/bin/env bash
# Fails when a configured build folder registers no tests for a part whose packages this machine
# has (issue 32): a part the README's test command promises must run, not vanish because an
# earlier configure left it out. Usage: scripts/check-parts.sh [BUILD_DIR] (default ./build).
#   Python tests (Python.*)        when pybind11-dev, python3-dev, python3-pytest and python3-numpy are installed
#   browser app module tests (Web.model, Web.kinematics, Web.cmml)   when node is
#   browser tests (Web.browser)    when node and chromium are
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "check-parts: $build is not a configured build folder" >&2
  exit 1
fi
installed() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || return 1
  done
}
listed="$(ctest --test-dir "$build" -N)"
failed=0
expect() {  # expect PART TEST_NAME_REGEX WHY
  if ! grep -Eq "Test +#[0-9]+: $2" <<<"$listed"; then
    echo "check-parts: $1 are not registered in $build although $3 (see the parts summary of the configure; scripts/configure.sh all switches every part on)" >&2
    failed=1
  fi
}
if installed pybind11-dev python3-dev python3-pytest python3-numpy; then
  expect "the Python tests" 'Python\.' "pybind11-dev, python3-dev, python3-pytest and python3-numpy are installed"
fi
if command -v node >/dev/null; then
  expect "the browser app's module tests" 'Web\.model' "node is installed"
  if command -v chromium >/dev/null || command -v chromium-browser >/dev/null; then
    expect "the browser tests" 'Web\.browser' "node and chromium are installed"
  fi
fi
if [ "$failed" -ne 0 ]; then exit 1; fi
echo "check-parts: every part whose packages are installed has its tests registered in $build" >&2
