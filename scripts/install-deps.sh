#!/usr/bin/env bash
# Installs the Debian 12 packages foldkit builds against, when any is missing. Extra packages a
# script needs beyond those (e.g. clang for scripts/test-tsan.sh) can be given as arguments.
# OMPL's CMake config links Boost.Serialization/Filesystem/System and ODE, which libompl-dev
# does not pull in, so they are listed explicitly.
set -euo pipefail

# --demo: only what building the foldkit CLI needs (scripts/demo.sh); the test, benchmark and
# experiment packages are left out. --serve: that and Node.js/npm for the browser app
# (scripts/serve.sh).
demo=0
web=1
if [ "${1:-}" = "--demo" ]; then
  demo=1
  web=0
  shift
elif [ "${1:-}" = "--serve" ]; then
  demo=1
  shift
fi

packages=(
  cmake g++ make ccache
  libeigen3-dev libboost-dev libboost-graph-dev
  libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
  libtinyxml2-dev nlohmann-json3-dev libcli11-dev libcgal-dev zlib1g-dev
  libompl-dev libode-dev libfcl-dev libccd-dev
  coinor-libclp-dev pkg-config libcpp-httplib-dev libsuitesparse-dev
  "$@"
)
if [ "$demo" -eq 0 ]; then
  packages+=(
    libbenchmark-dev libgtest-dev
    doxygen
    libceres-dev
    python3-matplotlib
    pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest
    ompl-demos
    chromium
  )
fi
# The browser app's packages come from npm (web/package-lock.json). Node.js and npm are installed
# only when missing: a Node.js from elsewhere (NodeSource) ships its own npm, which Debian's npm
# package conflicts with. Debian 12's Node.js is 18, which the app and its tests support.
if [ "$web" -eq 1 ]; then
  command -v node >/dev/null || packages+=(nodejs)
  command -v npm >/dev/null || packages+=(npm)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present" >&2
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null; then
  sudo=(sudo)
else
  echo "install-deps: missing packages and not root (no sudo): ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq "${missing[@]}" >&2
