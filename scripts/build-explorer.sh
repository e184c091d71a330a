#!/usr/bin/env bash
# Builds the explorer page (issue 26; docs/explorer.md) into build/explorer/: the WebAssembly core
# (scripts/build-wasm.sh), the npm packages pinned in explorer/package-lock.json (npm ci, from
# npm's registry, only when node_modules is missing or older than the lockfile), and the bundle
# (esbuild: explorer/build.mjs). The page then needs no network.
#   scripts/build-explorer.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build-wasm.sh
if [ ! -f explorer/node_modules/.package-lock.json ] ||
   [ explorer/package-lock.json -nt explorer/node_modules/.package-lock.json ]; then
  (cd explorer && npm ci --no-audit --no-fund --loglevel=error)
fi
node explorer/build.mjs
