#!/usr/bin/env bash
# Runs the viewer's browser tests: creates a venv with Playwright and Pillow from PyPI (pinned
# in requirements.txt; once, in <build-dir>/browser-venv), then drives Debian's Chromium.
#   tests/browser/run.sh <build-dir>          (needs <build-dir>/apps/hmira/hmira built with the viewer)
#   tests/browser/run.sh <build-dir> --large  (also: the ~2M-triangle gyroid page must render in < 5 s)
# Any missing piece (Chromium, the venv, the binary) is a failure, never a skip.
set -euo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ] || { [ $# -eq 2 ] && [ "$2" != --large ]; }; then echo "usage: $0 <build-dir> [--large]" >&2; exit 2; fi
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "$1" && pwd)"
export HMIRA_BIN="$build/apps/hmira/hmira"
[ -x "$HMIRA_BIN" ] || { echo "browser tests: $HMIRA_BIN not built" >&2; exit 1; }
venv="$(bash "$here/venv.sh" "$build/browser-venv")"
cd "$here"
"$venv/bin/python" test_viewer.py 2>&1
if [ "${2:-}" = --large ]; then
  large="$build/browser-large"
  mkdir -p "$large"
  "$HMIRA_BIN" mc gyroid "$large/gyroid.ply" -n 230 --quiet
  "$HMIRA_BIN" view "$large/gyroid.ply" "$large/gyroid.html"
  "$venv/bin/python" measure_large.py "$large/gyroid.html" 3
fi
