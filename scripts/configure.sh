#!/usr/bin/env bash
# Configures a build folder for one of the README's commands, so that the commands can run in
# any order on one folder (issue 32: the demo used to cache FOLDKIT_BUILD_PYTHON=OFF before the
# test command installed pybind11, and the tests then ran without Python, silently).
#
#   scripts/configure.sh all [DIR] [CMAKE_ARGS…]  every part, each switch set explicitly, and
#                                                 FOLDKIT_REQUIRE_ALL_PARTS: a part left out fails
#                                                 (scripts/build.sh, so scripts/test.sh)
#   scripts/configure.sh cli [DIR]                what the foldkit CLI needs (scripts/demo.sh)
#   scripts/configure.sh web [DIR]                the CLI and the browser app (scripts/serve.sh)
#
# cli and web configure a new folder with only what they need, and leave the switches of a
# folder that is configured already as they are (web only adds the browser app): a folder
# scripts/test.sh set up keeps its tests, Python and benchmarks. DIR defaults to ./build.
# The configure ends with the list of parts built and left out (cmake/FoldkitParts.cmake).
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
build="${2:-build}"
shift $(( $# < 2 ? $# : 2 ))
case "$mode" in
  all)
    exec cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DFOLDKIT_BUILD_TESTS=ON -DFOLDKIT_BUILD_BENCHMARKS=ON \
      -DFOLDKIT_BUILD_EXPERIMENTS=ON -DFOLDKIT_BUILD_WEB=ON -DFOLDKIT_BUILD_PYTHON=ON -DFOLDKIT_REQUIRE_ALL_PARTS=ON "$@" >&2
    ;;
  cli|web)
    web=()
    [ "$mode" = web ] && web=(-DFOLDKIT_BUILD_WEB=ON)
    if [ -f "$build/CMakeCache.txt" ]; then
      exec cmake -S . -B "$build" "${web[@]}" "$@" >&2
    fi
    [ "$mode" = cli ] && web=(-DFOLDKIT_BUILD_WEB=OFF)
    exec cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DFOLDKIT_BUILD_TESTS=OFF -DFOLDKIT_BUILD_BENCHMARKS=OFF \
      -DFOLDKIT_BUILD_EXPERIMENTS=OFF -DFOLDKIT_BUILD_PYTHON=OFF "${web[@]}" "$@" >&2
    ;;
  *)
    echo "usage: scripts/configure.sh all|cli|web [BUILD_DIR] [CMAKE_ARGS…]" >&2
    exit 2
    ;;
esac
