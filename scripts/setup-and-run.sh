#!/usr/bin/env bash
# Sets everything up on a fresh Debian machine and runs selfalign's main job.
#   1. installs the Debian dependencies (scripts/install-deps.sh, idempotent)
#   2. builds and installs selfalign into build/install (CLI: build/install/bin/selfalign) and
#      the Python module into .venv (scripts/install-python.sh: .venv/bin/python -c 'import selfalign')
#   3. builds the explorer page into build/explorer (scripts/build-explorer.sh: the WebAssembly
#      core and the npm packages of explorer/package-lock.json), so that scripts/explorer.sh
#      then serves it with no network
#   4. runs the main job on built-in defaults: `python -m selfalign reproduce` regenerates the
#      paper's figures, their data and a PASS/FAIL table of its claims into out/ (or $1)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}

bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"
cmake --install build/release >/dev/null
bash scripts/install-python.sh build/release
bash scripts/build-explorer.sh

# The main job: every figure of the paper, its data, report.md / index.html and the claims table.
.venv/bin/python -m selfalign reproduce --out "$out"
echo "open $out/index.html (or read $out/report.md); scripts/explorer.sh serves the explorer"
