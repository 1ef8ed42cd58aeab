#!/usr/bin/env bash
# Installs the Debian 12 packages swept needs (as root via apt-get; otherwise prints the command;
# the tests' and benchmarks' too: GoogleTest, Google Benchmark, FCL, OMPL, and the sample files of
# assimp, OpenCASCADE and FreeCAD that the tests read),
# the viewer's npm packages, and configures + builds the release preset; then installs the Python
# module for /usr/bin/python3 (as root; otherwise prints the PYTHONPATH line to use).
#   bash scripts/setup.sh            # packages + what a user runs: swept, swept-tools, the CAD module, Python
#   bash scripts/setup.sh --all      # packages + every target: the tests and the benchmarks too
#   SWEPT_SKIP_BUILD=1 bash scripts/setup.sh   # packages only
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libtbb-dev libassimp-dev libabsl-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  libtomlplusplus-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  assimp-testmodels occt-misc freecad-common
  libfcl-dev libompl-dev zlib1g-dev libminizip-dev libexpat1-dev
  chromium
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed python3-tqdm
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js/npm build the viewer; Debian's npm only where npm is missing (it conflicts with others).
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: please run as root:  apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

if [ -f viewer/package.json ] && [ ! -d viewer/node_modules ]; then
  (cd viewer && npm ci --no-audit --no-fund --loglevel=error)
fi

# The targets a user runs (swept builds swept-tools; the CAD module is loaded by both). `--all`
# builds the rest: the test programs and the benchmarks, which link GoogleTest, FCL and OMPL.
user_targets=(swept_cli swept_cad)
if [ "${1:-}" = "--all" ]; then
  build_targets=(all)
else
  build_targets=("${user_targets[@]}")
fi

if [ -z "${SWEPT_SKIP_BUILD:-}" ]; then
  cmake --preset release >/dev/null
  # The Python module, where it is configured (pybind11, Python's headers and NumPy found).
  if [ "${build_targets[0]}" != all ] && ninja -C build/release -t query swept_python >/dev/null 2>&1; then
    build_targets+=(swept_python)
  fi
  cmake --build --preset release -j"$(nproc)" --target "${build_targets[@]}"
  # The Python module (docs/python.md), built for Debian's /usr/bin/python3: as root it is
  # installed into /usr/local/lib/python3.X/dist-packages, on that interpreter's path.
  if compgen -G "build/release/python/swept/_swept*.so" >/dev/null; then
    if [ "$(id -u)" = 0 ]; then
      cmake --install build/release --component python >/dev/null
      echo "setup: Python module installed:  /usr/bin/python3 -c 'import swept'"
    else
      echo "setup: for the Python module:  export PYTHONPATH=$PWD/build/release/python"
    fi
  fi
fi
