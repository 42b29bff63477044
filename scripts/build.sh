#!/usr/bin/env bash
# Configures and builds foldkit in ./build (Release): everything — libraries, CLI, tests,
# benchmarks, experiments and the browser app's packages (npm). Extra arguments go to cmake's
# configure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFOLDKIT_BUILD_TESTS=ON -DFOLDKIT_BUILD_BENCHMARKS=ON \
  -DFOLDKIT_BUILD_EXPERIMENTS=ON -DFOLDKIT_BUILD_WEB=ON "$@" >&2
cmake --build build -j "$(nproc)" >&2
