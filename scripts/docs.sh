#!/usr/bin/env bash
# Builds hmira's API reference with Doxygen (Debian package `doxygen`) into build/docs/html,
# and fails if Doxygen warns: every public entity of include/hmira must be documented.
# Usage: bash scripts/docs.sh [output dir]      (default: build/docs)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null || bash scripts/install-deps.sh
out="${1:-build/docs}"
mkdir -p "$out"
log="$out/doxygen-warnings.log"
if HMIRA_DOCS_OUT="$out" doxygen docs/Doxyfile 2>"$log"; then
  status=0
else
  status=$?
fi
if [ -s "$log" ]; then
  cat "$log" >&2
  echo "docs: $(grep -cE ': (warning|error): ' "$log" || true) Doxygen warning(s); the API reference must build warning-free" >&2
  exit 1
fi
[ "$status" -eq 0 ] || { echo "docs: doxygen failed (exit $status)" >&2; exit "$status"; }
echo "docs: $out/html/index.html"
