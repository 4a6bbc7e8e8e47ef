#!/usr/bin/env bash
# Extracts the real meshes and volumes that Debian's libcgal-demo ships into DEST
# (default: build/test-data). Nothing of that data is committed to this repository.
set -euo pipefail
dest="${1:-build/test-data}"
archive=""
for a in /usr/share/doc/libcgal-demo/data.tar.gz /usr/share/doc/libcgal-dev/data.tar.gz; do
  [ -f "$a" ] && { archive="$a"; break; }
done
if [ -z "$archive" ]; then
  echo "test-data: libcgal-demo's data.tar.gz not found; run scripts/install-deps.sh" >&2
  exit 1
fi
if [ -f "$dest/.extracted" ]; then exit 0; fi
mkdir -p "$dest"
tar -xzf "$archive" -C "$dest" --strip-components=1 --wildcards 'data/meshes/*' 'data/images/*' 'data/points_3/*' 2>/dev/null \
  || tar -xzf "$archive" -C "$dest" --strip-components=1 --wildcards 'data/meshes/*' 'data/images/*'
touch "$dest/.extracted"
echo "test-data: real meshes and volumes in $dest/meshes and $dest/images"
