#!/usr/bin/env bash
# Installs selfalign's build, test and figure dependencies from Debian's packages.
# Idempotent: packages already present are skipped; apt-get runs only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libnlopt-cxx-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libtbb-dev
  libboost-dev libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pil python3-pytest python3-venv
  python3-distributed python3-mpi4py openmpi-bin python3-scipy
  libsiconos-numerics-dev libceres-dev
  emscripten nodejs chromium
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm (the explorer's pinned packages): Debian's package where no npm came with nodejs (a
# nodejs built elsewhere may carry its own npm, which Debian's would conflict with).
command -v npm >/dev/null || missing+=(npm)

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
