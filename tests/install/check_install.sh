#!/usr/bin/env bash
# Installs the build into a temporary prefix, then builds and runs a consumer project against it
# with find_package(swept), and checks the pkg-config file.   check_install.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
cmake -S "$src/tests/install/consumer" -B "$tmp/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$tmp/consumer" >/dev/null
"$tmp/consumer/consumer"
PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig" pkg-config --cflags --libs swept | grep -q -- "-lswept_query"
test -x "$tmp/prefix/bin/swept"
# The CAD reader is a module loaded on first use: the installed swept finds the installed module
# (not the build tree's) from the moved prefix, and reads STEP with it.
"$tmp/prefix/bin/swept" --version | grep -qxF "CAD reader (STEP, IGES, OCCT .brep): $tmp/prefix/lib/swept/libswept_cad.so"
"$tmp/prefix/bin/swept" mesh-stats "$src/tests/data/io/box_mm.step" --json | grep -q '"triangles": 12'
# ... also when it is run by name from PATH (then argv[0] is no location), from another folder.
(cd "$tmp" && PATH="$tmp/prefix/bin:$PATH" swept --version) |
  grep -qxF "CAD reader (STEP, IGES, OCCT .brep): $tmp/prefix/lib/swept/libswept_cad.so"
# Programs that never read CAD do not load OpenCASCADE at start-up; `swept` itself links neither
# OpenCASCADE's modelling libraries nor FCL: `swept scene` and `swept bench` run the installed
# swept-tools (libexec), found from the moved prefix too.
if ldd "$tmp/prefix/bin/swept" | grep -qE "libTK|libfcl"; then
  echo "install: the swept binary links OpenCASCADE or FCL at start-up" >&2
  exit 1
fi
"$tmp/prefix/bin/swept" --version |
  grep -qxF "scenes and benchmarks (swept scene, swept bench): $tmp/prefix/libexec/swept/swept-tools"
(cd "$tmp" && PATH="$tmp/prefix/bin:$PATH" swept scene --list) | grep -q "^tunnel-console"
(cd "$tmp" && PATH="$tmp/prefix/bin:$PATH" swept bench --help) | grep -q "queries"
# The Python module, when it was built, imports from the prefix's site directory.
for site in "$tmp"/prefix/lib/python3*/dist-packages; do
  [ -d "$site/swept" ] || continue
  python=$(grep -m1 '^SWEPT_PYTHON_EXECUTABLE:' "$build/CMakeCache.txt" | cut -d= -f2-)
  (cd "$tmp" && PYTHONPATH="$site" "${python:-/usr/bin/python3}" -c "import swept, swept.study; assert swept.__file__.startswith('$site')")
  echo "install: the Python module imports from $site"
done
echo "install: find_package(swept), pkg-config, the swept binary and swept-tools work"
