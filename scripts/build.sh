#!/usr/bin/env bash
# Configures and builds foldkit in ./build (Release): everything — libraries, CLI, tests,
# benchmarks, experiments, the Python module and the browser app's packages (npm), each switched
# on explicitly, whatever an earlier configure of ./build (scripts/demo.sh) cached; a part that
# cannot be built is a configure error (scripts/configure.sh all). Extra arguments go to cmake's
# configure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/configure.sh all build "$@"
cmake --build build -j "$(nproc)" >&2
