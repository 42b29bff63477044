#!/usr/bin/env bash
# ThreadSanitizer (clang) on what runs in several threads at once: validity checks shared by
# OMPL's parallel planners (PRM, PRM*) with collisions on, the plan's and the fold's pipelines,
# and the Carpenter's rule checks split over two threads. Builds only the three test programs it
# runs, in ./build-tsan; any report fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh clang
# -O1 keeps the planners' timed runs meaningful under TSan's slowdown; Debug keeps assertions.
flags="-O1 -g -fsanitize=thread -fno-omit-frame-pointer"
cmake -S . -B build-tsan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DFOLDKIT_BUILD_BENCHMARKS=OFF -DFOLDKIT_BUILD_PYTHON=OFF -DFOLDKIT_BUILD_WEB=OFF \
  -DFOLDKIT_BUILD_EXPERIMENTS=OFF -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" >&2
cmake --build build-tsan -j "$(nproc)" --target foldkit_statespaces_tests foldkit_planners_tests foldkit_folding_tests >&2
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/scripts/tsan.supp"
./build-tsan/test/foldkit_statespaces_tests --gtest_filter='FoldValidity.*'
# The plan's own threads: the replay beside the waypoints, the straight plan beside the planner.
./build-tsan/test/foldkit_planners_tests --gtest_filter='Plan.ThreadedPlanners*:ReplayPipeline.*:StraightPlan.*'
# The fold's replay beside the folding; the carried field's all-pairs checks on two threads.
./build-tsan/test/foldkit_folding_tests --gtest_filter='ProjectedFoldingReplay.*:CarpenterRepair.*'
