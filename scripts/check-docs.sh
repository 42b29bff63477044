#!/usr/bin/env bash
# Builds the API reference (target `docs`, cmake/FoldkitDocs.cmake) in an already configured
# build folder and fails when Doxygen warned: an undocumented public symbol, a @param that
# names no parameter, a broken reference.
#   scripts/check-docs.sh [BUILD]    (default: the build folder of this checkout)
# Exit status: 0 no warnings, 1 warnings (printed), 2 no usable build folder.
set -euo pipefail
build=${1:-"$(dirname "$0")/../build"}
log="$build/docs/doxygen-warnings.txt"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  echo "check-docs: $build is not a configured build folder (run scripts/build.sh or cmake first)" >&2
  exit 2
fi
if [[ ! -f "$build/docs/Doxyfile" ]]; then  # configured only when Doxygen was found
  echo "check-docs: $build has no 'docs' target (is Doxygen installed? reconfigure after installing it)" >&2
  exit 2
fi

cmake --build "$build" --target docs
if [[ -s "$log" ]]; then
  cat "$log" >&2
  echo "check-docs: $(grep -c 'warning:' "$log" || true) Doxygen warnings (full log: $log)" >&2
  exit 1
fi
echo "check-docs: no Doxygen warnings; reference in $build/docs/html/index.html"
