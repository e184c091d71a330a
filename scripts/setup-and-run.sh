#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs selfalign's main job.
#   1. installs the Debian dependencies (scripts/install-deps.sh, idempotent)
#   2. builds and installs selfalign into build/install (CLI: build/install/bin/selfalign)
#   3. runs the main job on built-in defaults, writing to out/ (or the folder given as $1)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}

bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
cmake --install build/release >/dev/null
bin=build/install/bin/selfalign

mkdir -p "$out"
echo "== selfalign simulate (defaults: Sect. 7.2 setting) -> $out/trajectory.csv"
"$bin" simulate --out "$out/trajectory.csv" --summary "$out/summary.json"
cat "$out/summary.json"
