#!/usr/bin/env bash
# The explorer in one command: builds what is missing (scripts/build-explorer.sh) and serves
# build/explorer/ on the loopback interface, opening it in a browser where one can be opened.
#   scripts/explorer.sh [port]      (default 8765; Ctrl-C stops the server)
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  cat <<'USAGE'
Usage: scripts/explorer.sh [PORT]
Builds the explorer if needed (scripts/build-explorer.sh: the WebAssembly core, the pinned npm
packages, the bundle) and serves build/explorer/ on http://127.0.0.1:PORT/ (default 8765),
opening a browser where a display exists. Ctrl-C stops the server. docs/explorer.md.
USAGE
  exit 0
fi
port="${1:-8765}"
case "$port" in
  ''|*[!0-9]*) echo "invalid port = $port: must be an integer in [1, 65535]" >&2; exit 2 ;;
esac
if [ "$port" -lt 1 ] || [ "$port" -gt 65535 ]; then
  echo "invalid port = $port: must be an integer in [1, 65535]" >&2; exit 2
fi
[ -f /usr/bin/node ] || bash scripts/install-deps.sh
bash scripts/build-explorer.sh
url="http://127.0.0.1:$port/"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && command -v xdg-open >/dev/null; then
  (sleep 1; xdg-open "$url" >/dev/null 2>&1 || true) &
fi
exec node explorer/serve.mjs build/explorer "$port"
