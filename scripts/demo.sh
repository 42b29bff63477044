#!/usr/bin/env bash
# Sets up, builds and runs the end-to-end demo; its outputs go to ./foldkit-demo. Installs and
# builds only what the foldkit CLI needs (scripts/test.sh builds everything); a ./build that
# scripts/test.sh configured keeps its switches (scripts/configure.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --demo
bash scripts/configure.sh cli build
cmake --build build -j "$(nproc)" --target foldkit >&2
./build/apps/foldkit demo -o foldkit-demo
