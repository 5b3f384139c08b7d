#!/usr/bin/env bash
# Installs the browser's JavaScript (three.js for the 3D view) from the npm registry, exactly as
# package-lock.json pins it, into tools/browser/node_modules, which the browser serves itself
# (no CDN). Does nothing when the pinned version is there already. Run by tools/pg/install_deps.sh.
set -euo pipefail

cd "$(dirname "$0")"
# The first "version" of each file: three's in the lock (the project itself has none), and in
# the installed package.json.
version() { [[ -f "$1" ]] && sed -n 's/^ *"version": "\(.*\)",$/\1/p' "$1" | head -n 1; }
want=$(version package-lock.json)
have=$(version node_modules/three/package.json || true)
if [[ -n "$want" && "$want" == "$have" ]]; then
  echo "deps: three $have present (tools/browser/node_modules)"
  exit 0
fi
command -v npm >/dev/null || { echo "deps: npm not found (Debian's npm package)" >&2; exit 1; }
# ci: exactly the lock file, integrity checked; no install scripts run.
npm ci --ignore-scripts --no-audit --no-fund --loglevel=error
echo "deps: three $(version node_modules/three/package.json) installed (tools/browser/node_modules)"
