#!/usr/bin/env bash
# Sets up, builds and runs the end-to-end demo; its outputs go to ./foldkit-demo. Installs and
# builds only what the foldkit CLI needs (scripts/test.sh builds everything).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --demo
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFOLDKIT_BUILD_TESTS=OFF -DFOLDKIT_BUILD_BENCHMARKS=OFF \
  -DFOLDKIT_BUILD_EXPERIMENTS=OFF >&2
cmake --build build -j "$(nproc)" --target foldkit >&2
./build/apps/foldkit demo -o foldkit-demo
