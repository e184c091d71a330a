#!/usr/bin/env bash
# Runs every test: installs the Debian dependencies (idempotent), builds, and runs ctest.
#   scripts/test.sh          Release build (build/release), all tests, then the Python module's
#                            pytest suite (python/tests) against .venv (scripts/install-python.sh),
#                            then the WebAssembly core (scripts/build-wasm.sh) against the CLI
#                            (node --test wasm/tests/), then the explorer page in headless
#                            chromium (scripts/build-explorer.sh; node --test explorer/tests/;
#                            screenshots and timings in build/explorer-artifacts/)
#   scripts/test.sh --asan   Debug build with AddressSanitizer + UBSan (build/asan), all tests
set -euo pipefail
cd "$(dirname "$0")/.."

preset=release
[ "${1:-}" = "--asan" ] && preset=asan

bash scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
# Python module: release only (a sanitized extension cannot load in an unsanitized python).
if [ "$preset" = release ]; then
  bash scripts/install-python.sh build/release
fi
ctest --preset "$preset"
if [ "$preset" = release ]; then
  .venv/bin/python -m pytest python/tests -q
  # The C++ core in WebAssembly (issue 26) against the native CLI just built, then the page
  # (built with it by build-explorer.sh) in a real browser.
  bash scripts/build-explorer.sh
  export SELFALIGN_CLI="$PWD/build/release/apps/selfalign/selfalign"
  node --test wasm/tests/
  node --test explorer/tests/
fi
