#!/usr/bin/env bash
# Creates (once) the venv the browser tests and scripts/gallery.sh use, with the packages pinned
# in requirements.txt, and prints its path.   tests/browser/venv.sh <venv-dir>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
venv="$1"
if ! cmp -s "$here/requirements.txt" "$venv/.hmira-requirements" 2>/dev/null; then
  python3 -m venv "$venv" >&2
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$here/requirements.txt" >&2
  cp "$here/requirements.txt" "$venv/.hmira-requirements"
fi
echo "$(cd "$venv" && pwd)"
