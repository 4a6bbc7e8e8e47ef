#!/usr/bin/env bash
# Checks that the committed viewer bundle, dist/hmira-viewer.js, is what the sources make now:
# rebuilds it (viewer/build.sh: npm ci of the pinned three.js and esbuild, then esbuild, which
# is deterministic) into a temporary file and compares. Fails, with a diff summary, when
# src/*.js, build.mjs or package-lock.json changed without the bundle being rebuilt.
#   bash viewer/check-bundle.sh        (needs node and npm; CI runs it)
# To update the bundle: bash viewer/build.sh, then commit viewer/dist/hmira-viewer.js.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
committed="$here/dist/hmira-viewer.js"
[ -f "$committed" ] || { echo "viewer: $committed is missing (bash viewer/build.sh writes it; commit it)" >&2; exit 1; }
fresh="$(mktemp "${TMPDIR:-/tmp}/hmira-viewer.XXXXXX.js")"
trap 'rm -f "$fresh"' EXIT
bash "$here/build.sh" "$fresh" >/dev/null
if ! cmp -s "$committed" "$fresh"; then
  echo "viewer: viewer/dist/hmira-viewer.js is stale: it differs from a fresh build of viewer/src" \
       "($(wc -c <"$committed") bytes committed, $(wc -c <"$fresh") built)." >&2
  echo "viewer: run 'bash viewer/build.sh' and commit viewer/dist/hmira-viewer.js" >&2
  exit 1
fi
echo "viewer: viewer/dist/hmira-viewer.js matches a fresh build"
