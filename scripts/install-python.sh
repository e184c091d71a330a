#!/usr/bin/env bash
# Installs the Python module `selfalign` into the repository's virtual environment .venv, so that
# `.venv/bin/python -c 'import selfalign'` works without PYTHONPATH.
#   scripts/install-python.sh BUILD_DIR      e.g. build/release (built with SELFALIGN_BUILD_PYTHON)
# Idempotent: creates .venv once (Debian's /usr/bin/python3 with --system-site-packages, so
# NumPy, matplotlib and pytest come from the Debian packages), then replaces the installed
# package with the build's (cmake --install BUILD_DIR --component python).
set -euo pipefail
cd "$(dirname "$0")/.."

build=${1:?usage: scripts/install-python.sh BUILD_DIR}
python=/usr/bin/python3
venv=.venv

ls "$build"/python/selfalign/_selfalign*.so >/dev/null 2>&1 || {
  echo "install-python: no extension module in $build/python/selfalign; build first" \
       "(cmake --build $build)" >&2
  exit 1
}

# (Re)create the venv unless it is already one of $python with the system site packages.
cfg=$venv/pyvenv.cfg
if [ ! -x "$venv/bin/python" ] || ! grep -qx 'include-system-site-packages = true' "$cfg" ||
   [ "$(readlink -f "$venv/bin/python")" != "$(readlink -f "$python")" ]; then
  echo "install-python: creating $venv ($python, --system-site-packages)"
  rm -rf "$venv"
  "$python" -m venv --system-site-packages --without-pip "$venv"
fi

site=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
rm -rf "$site/selfalign"
cmake --install "$build" --component python --prefix "$venv" >/dev/null
[ -f "$site/selfalign/__init__.py" ] || {
  echo "install-python: the package did not land in $site (python version mismatch?)" >&2
  exit 1
}
"$venv/bin/python" -c 'import selfalign; print("install-python: selfalign", selfalign.__version__, "->", selfalign.__file__)'
