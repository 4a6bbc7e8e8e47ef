#!/usr/bin/env bash
# `hmira mc` reads .raw and .inr volumes slab by slab: its peak memory (/usr/bin/time
# -v) on a volume four times the allowance stays within a few slabs plus the output mesh, and
# its output is byte for byte the whole-volume path's (a FIFO or a .inr.gz is read whole).
#   usage: mc_slabs_rss.sh HMIRA_BINARY [TEST_DATA_DIR]
set -euo pipefail
hmira=$(realpath "$1")
data=${2:+$(realpath "$2")}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"

# 1. Peak RSS: a 256 MiB uint8 volume (sparse: zeros, plus eight 64-sample runs of 255 that
# make small closed surfaces), meshed 8 slices (8 MiB) at a time.
nx=1024 ny=1024 nz=256
truncate -s $((nx * ny * nz)) big.raw
run=$(head -c 64 /dev/zero | tr '\0' '\377')
for s in 1 2 3 4 5 6 7 8; do
  k=$((s * 29)) j=$((s * 101)) i=$((s * 97))
  for dk in 0 1 2; do for dj in 0 1 2; do
    printf '%s' "$run" | dd of=big.raw bs=1 seek=$(((k + dk) * nx * ny + (j + dj) * nx + i)) conv=notrunc status=none
  done; done
done
/usr/bin/time -v "$hmira" mc big.raw big.ply --dims $nx,$ny,$nz --type uint8 --iso 128 --inside above --slab-slices 8 \
  2> time.txt > out.txt
cat out.txt
rss_kib=$(sed -n 's/.*Maximum resident set size (kbytes): //p' time.txt)
echo "volume $((nx * ny * nz / 1048576)) MiB, slab 8 slices ($((8 * nx * ny / 1048576)) MiB), peak RSS $((rss_kib / 1024)) MiB"
# Each 64 x 3 x 3 box of 255s: one vertex per outward sample edge, 2 (64*3 + 64*3 + 3*3) = 786,
# and, closed and of genus 0, 2V - 4 = 1568 triangles; eight boxes.
grep -q "big.ply: 6288 vertices, 12544 triangles" out.txt || { echo "unexpected mesh size" >&2; exit 1; }
# The whole volume would need 256 MiB; a slab, its bit rows and counters need about 12 MiB.
if [ "$rss_kib" -gt $((64 * 1024)) ]; then echo "peak RSS ${rss_kib} KiB exceeds 64 MiB" >&2; exit 1; fi

# 2. The slab path writes exactly what the whole-volume path writes: a FIFO is read whole.
head -c $((96 * 80 * 40)) /dev/urandom > small.raw
"$hmira" mc small.raw slabs.ply --dims 96,80,40 --type uint8 --iso 100 --slab-slices 3 -q
mkfifo whole.raw
cat small.raw > whole.raw &
"$hmira" mc whole.raw whole.ply --dims 96,80,40 --type uint8 --iso 100 -q
wait
cmp slabs.ply whole.ply
echo "uint8 .raw: slab-by-slab output equals the whole-volume output"
# int16 big-endian, other slab sizes.
head -c $((50 * 41 * 33 * 2)) /dev/urandom > s16.raw
for s in 1 7 40; do
  "$hmira" mc s16.raw s16-$s.ply --dims 50,41,33 --type int16 --endian big --iso 0 --slab-slices $s -q
done
mkfifo w16.raw
cat s16.raw > w16.raw &
"$hmira" mc w16.raw w16.ply --dims 50,41,33 --type int16 --endian big --iso 0 -q
wait
for s in 1 7 40; do cmp s16-$s.ply w16.ply; done
echo "int16 big-endian .raw: equal for slabs of 1, 7 and 40 slices"

# 3. An uncompressed .inr (the skull) equals its gzipped copy, which is read whole.
if [ -n "$data" ] && [ -f "$data/images/skull_2.9.inr" ]; then
  cp "$data/images/skull_2.9.inr" skull.inr
  gzip -c skull.inr > skull.inr.gz
  "$hmira" mc skull.inr a.ply --iso 2.9 --inside above --slab-slices 5 -q
  "$hmira" mc skull.inr.gz b.ply --iso 2.9 --inside above -q
  cmp a.ply b.ply
  echo "skull .inr: slab-by-slab output equals the .inr.gz output"
fi

# 4. A NaN in a float volume is refused, naming the sample, as the whole-volume reader does.
head -c $((8 * 8 * 8 * 4)) /dev/zero > nan.raw
printf '\x00\x00\xc0\x7f' | dd of=nan.raw bs=1 seek=$(((5 * 64 + 2 * 8 + 3) * 4)) conv=notrunc status=none
if "$hmira" mc nan.raw nan.ply --dims 8,8,8 --slab-slices 2 2> err.txt; then echo "NaN accepted" >&2; exit 1; fi
grep -q "nan.raw: sample (3, 2, 5) is NaN" err.txt || { cat err.txt >&2; exit 1; }
test ! -e nan.ply
echo "NaN refused: $(cat err.txt)"
