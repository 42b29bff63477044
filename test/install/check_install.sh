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
# As on a machine without OMPL, FCL and Clp: the geometry + io components must not look for them.
cmake -S "$source_dir/examples/use_foldkit" -B "$prefix/bare" -DCMAKE_PREFIX_PATH="$prefix/install" \
  -DCMAKE_DISABLE_FIND_PACKAGE_ompl=ON -DCMAKE_DISABLE_FIND_PACKAGE_fcl=ON -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" >/dev/null
cmake --build "$prefix/bare" >/dev/null
test "$("$prefix/bare/use_foldkit")" = "15 actors, 22 joints"
# Asking for the planners without them fails at configure time, with foldkit's message.
if cmake -S "$source_dir/examples/use_foldkit" -B "$prefix/no-planners" -DCMAKE_PREFIX_PATH="$prefix/install" \
  -DCMAKE_DISABLE_FIND_PACKAGE_ompl=ON -DFOLDKIT_CONSUMER_COMPONENTS=planners >/dev/null 2>&1; then
  echo "check_install: find_package(foldkit COMPONENTS planners) succeeded without OMPL" >&2
  exit 1
fi
"$prefix/install/bin/foldkit" --version
# The browser app, when built: the installed foldkit serve finds it beside itself and serves the
# page, its modules and three.js's from share/foldkit/web.
if [ -f "$prefix/install/share/foldkit/web/index.html" ]; then
  (cd "$prefix" && exec "$prefix/install/bin/foldkit" serve --port 0 --root "$prefix" 2>"$prefix/serve.log") &
  server=$!
  trap 'kill "$server" 2>/dev/null || true; rm -rf "$prefix"' EXIT
  for _ in $(seq 1 100); do grep -q 'http://' "$prefix/serve.log" 2>/dev/null && break; sleep 0.1; done
  url=$(grep -o 'http://[0-9.:]*/' "$prefix/serve.log")
  /usr/bin/python3 - "$url" "$prefix/install/share/foldkit/web" <<'PY'
import sys, urllib.request, urllib.error
url, web = sys.argv[1], sys.argv[2]
direct = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # never through a proxy
def get(path):
    try:
        with direct.open(url + path, timeout=10) as r:
            return r.status, r.read()
    except urllib.error.HTTPError as e:
        return e.code, b""
assert get("")[1] == open(web + "/index.html", "rb").read(), "GET / is not the installed page"
for path in ["src/app.js", "node_modules/three/build/three.module.js", "node_modules/three/examples/jsm/controls/OrbitControls.js"]:
    assert get(path)[0] == 200, path
assert get("node_modules/three/package.json")[0] == 404
print("serve: the installed app is served")
PY
  kill $server
fi
# The Python package, when built: importable from the installed tree alone.
module=$(find "$prefix/install" -name '_foldkit*.so' | head -n 1)
if [ -n "$module" ]; then
  site=$(dirname "$(dirname "$module")")
  (cd "$prefix" && PYTHONPATH="$site" /usr/bin/python3 -c \
    "import foldkit; p = foldkit.generators.miura(3, 3); s = foldkit.fold(p, 0.3).states[-1]; assert foldkit.dof(p, s).dof == 1; print('python:', p)")
fi
