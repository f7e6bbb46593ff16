#!/usr/bin/env bash
# Every test: dependencies, build, then ctest (C++, Python, CLI, FreeCAD headless and GUI).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
