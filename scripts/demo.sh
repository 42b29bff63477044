#!/usr/bin/env bash
# Sets up, builds and runs the end-to-end demo; its outputs go to ./foldkit-demo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/apps/foldkit demo -o foldkit-demo
