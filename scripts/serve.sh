#!/usr/bin/env bash
# Sets up, builds the foldkit CLI and the browser app, writes the demo's Miura-ori and its fold
# into ./foldkit-serve and opens them in `foldkit serve` (docs/SERVE.md): open the printed
# address in a browser. Extra arguments go to foldkit serve (e.g. --port 8081).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --serve
bash scripts/configure.sh web build
cmake --build build -j "$(nproc)" --target foldkit foldkit_web >&2
mkdir -p foldkit-serve
./build/apps/foldkit generate miura --rows 4 --cols 4 -o foldkit-serve/miura-4x4.pmml
./build/apps/foldkit fold foldkit-serve/miura-4x4.pmml --fraction 0.9 -o foldkit-serve/miura-4x4-folded.cmml
exec ./build/apps/foldkit serve --root foldkit-serve miura-4x4.pmml miura-4x4-folded.cmml "$@"
