#!/usr/bin/env bash
# Builds the viewer bundle `hmira view` embeds: installs the pinned three.js and esbuild from
# package-lock.json (npm ci, once) and writes dist/hmira-viewer.js. Needs node and npm.
#   viewer/build.sh [OUT.js]
# Then (re)configure CMake: it embeds the bundle into the hmira binary.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
command -v node >/dev/null && command -v npm >/dev/null || {
  echo "viewer: node and npm are needed to build the viewer bundle (scripts/install-deps.sh installs them)" >&2; exit 1; }
cd "$here"
# node_modules/.hmira-lock: the lock file the installed modules came from (reinstall when it changes).
if ! cmp -s package-lock.json node_modules/.hmira-lock 2>/dev/null; then
  npm ci --no-audit --no-fund --loglevel=error
  cp package-lock.json node_modules/.hmira-lock
fi
node build.mjs "$@"
