#!/usr/bin/env bash
# Runs every test: installs the Debian dependencies (idempotent), builds, and runs ctest.
#   scripts/test.sh          Release build (build/release), all tests
#   scripts/test.sh --asan   Debug build with AddressSanitizer + UBSan (build/asan), all tests
set -euo pipefail
cd "$(dirname "$0")/.."

preset=release
[ "${1:-}" = "--asan" ] && preset=asan

bash scripts/install-deps.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
ctest --preset "$preset"
