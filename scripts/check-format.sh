#!/usr/bin/env bash
# Checks that every tracked C++ file is formatted by the committed .clang-format, with Debian 12's
# clang-format-16, the version scripts/install-deps.sh installs: another version formats some
# constructs differently. Prints each file that deviates and exits 1; `clang-format-16 -i <file>`
# fixes one.
set -euo pipefail
cd "$(dirname "$0")/.."
cf=$(command -v clang-format-16 || true)
[ -n "$cf" ] || { echo "check-format: clang-format-16 is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
mapfile -t files < <(git ls-files '*.hpp' '*.cpp' '*.h' '*.cc')
bad=0
for f in "${files[@]}"; do
  "$cf" --dry-run --Werror "$f" >/dev/null 2>&1 || { echo "check-format: $f is not formatted (clang-format-16 -i $f)"; bad=1; }
done
[ "$bad" -eq 0 ] && echo "check-format: ${#files[@]} files formatted"
exit "$bad"
