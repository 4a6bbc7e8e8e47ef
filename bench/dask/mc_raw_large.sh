#!/usr/bin/env bash
# `hmira mc` slab by slab on a large .raw volume (default 12 GiB of uint8: 2048 x 2048 x 3072):
# peak RSS from /usr/bin/time -v, against the issue's target of 3 GiB plus the output mesh.
# The file is sparse (zeros) with 64 boxes of 255s, so it costs no disk; reading it still goes
# through pread and the page cache like any file. HMIRA_CLI: the binary (default build/apps/hmira/hmira).
set -euo pipefail
gib=${1:-12}
hmira=${HMIRA_CLI:-build/apps/hmira/hmira}
nx=2048 ny=2048
nz=$((gib * 1024 * 1024 * 1024 / (nx * ny)))
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
truncate -s $((nx * ny * nz)) "$tmp/big.raw"
run=$(head -c 256 /dev/zero | tr '\0' '\377')
for s in $(seq 1 64); do
  k=$((s * (nz - 8) / 65)) j=$(((s * 523) % (ny - 8))) i=$(((s * 331) % (nx - 300)))
  for dk in 0 1 2 3; do for dj in 0 1 2 3; do
    printf '%s' "$run" | dd of="$tmp/big.raw" bs=1 seek=$(((k + dk) * nx * ny + (j + dj) * nx + i)) conv=notrunc status=none
  done; done
done
echo "volume: $nx x $ny x $nz uint8 = $(( $(stat -c %s "$tmp/big.raw") / 1048576 )) MiB; machine $(free -g | awk '/Mem:/ {print $2}') GiB"
/usr/bin/time -v "$hmira" mc "$tmp/big.raw" "$tmp/out.ply" --dims $nx,$ny,$nz --type uint8 --iso 128 --inside above 2> "$tmp/time.txt"
grep -E "Maximum resident|Elapsed \(wall" "$tmp/time.txt"
rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$tmp/time.txt")
echo "peak RSS $((rss / 1024)) MiB (target: below 3072 MiB plus the output mesh at 24 B/vertex + 12 B/triangle)"
