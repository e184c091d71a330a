#!/usr/bin/env bash
# Builds the C++ core in WebAssembly (issue 26; wasm/CMakeLists.txt) with Debian's emscripten:
# build/wasm/selfalign_core.js + .wasm. Single-threaded (no oneTBB), no NLopt or Ceres.
#   scripts/build-wasm.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# Debian's emscripten runs its JavaScript tools with `node`; they need Debian's node modules
# (acorn), which a node that is not Debian's does not search.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
if [ ! -f build/wasm/build.ninja ]; then
  emcmake cmake -S wasm -B build/wasm -G Ninja >/dev/null
fi
cmake --build build/wasm -j "$(nproc)"
