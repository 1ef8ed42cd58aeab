#!/usr/bin/env bash
# Sets everything up and runs the whole test suite (release build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --all
ctest --preset release -j"$(nproc)" --timeout 900
