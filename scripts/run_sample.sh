#!/usr/bin/env bash
# The main job on a bundled sample: analyse the notch and say where the results are.
# Usage: bash scripts/run_sample.sh [PART] (default samples/notch.step)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
part="${1:-samples/notch.step}"
out="out/$(basename "${part%.*}")"
build/bin/framefix analyze "$part" --out "$out"
echo "open $out/*.vtk in ParaView; the report is $out/report.json"
