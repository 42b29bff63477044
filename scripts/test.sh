#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite. Fails before running anything when a part whose
# packages are installed registered no tests (scripts/check-parts.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
bash scripts/check-parts.sh build
ctest --test-dir build --output-on-failure -j "$(nproc)"
