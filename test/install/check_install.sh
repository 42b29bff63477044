#!/usr/bin/env bash
# Installs the build tree into a temporary prefix and builds examples/use_foldkit against it
# with find_package(foldkit), as another project would.
set -euo pipefail
build_dir=$1
source_dir=$2
cxx_flags=${3:-}     # the build's own flags (sanitizers), so the consumer links with them
linker_flags=${4:-}
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build_dir" --prefix "$prefix/install" >/dev/null
test -x "$prefix/install/bin/foldkit"
test -f "$prefix/install/include/foldkit/geometry/crease_pattern.hpp"
cmake -S "$source_dir/examples/use_foldkit" -B "$prefix/consumer" -DCMAKE_PREFIX_PATH="$prefix/install" \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" >/dev/null
cmake --build "$prefix/consumer" >/dev/null
out=$("$prefix/consumer/use_foldkit")
echo "$out"
test "$out" = "15 actors, 22 joints"
"$prefix/install/bin/foldkit" --version
