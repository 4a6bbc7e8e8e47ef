#!/usr/bin/env bash
# Reading is bounded: peak memory (/usr/bin/time -v) of reading hostile inputs
# stays below what the input may legitimately need plus 64 MiB:
#  - a .inr.gz gzip bomb (1 GiB of zeros after a header declaring 16 MiB of samples);
#  - /dev/zero read as a mesh with a 64 MiB input limit.
# Usage: bounded_read_rss.sh PATH/TO/bounded_read_probe
set -euo pipefail
probe="$1"
[ -x /usr/bin/time ] || { echo "bounded_read_rss: /usr/bin/time missing (apt install time)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0

# check NAME LIMIT_KIB KIND FILE CAP: runs the probe, which must refuse the file, under the limit.
check() {
  local name="$1" limit_kib="$2" kind="$3" file="$4" cap="$5"
  if ! /usr/bin/time -v -o "$work/time.txt" "$probe" "$kind" "$file" "$cap" > "$work/out.txt" 2>&1; then
    echo "bounded_read_rss: $name: not refused: $(cat "$work/out.txt")" >&2
    status=1
    return
  fi
  local rss
  rss="$(sed -n 's/^[[:space:]]*Maximum resident set size (kbytes): //p' "$work/time.txt")"
  echo "bounded_read_rss: $name: peak RSS ${rss} KiB (limit ${limit_kib} KiB): $(cat "$work/out.txt")"
  if [ -z "$rss" ] || [ "$rss" -ge "$limit_kib" ]; then
    echo "bounded_read_rss: $name: peak RSS ${rss:-?} KiB is not below ${limit_kib} KiB" >&2
    status=1
  fi
}

# The bomb: a 256^3 uint8 volume (16 MiB declared) followed by 1 GiB of zeros, built as
# concatenated gzip members so it takes no time to make.
python3 - "$work/bomb.inr.gz" <<'PY'
import gzip, sys, zlib
head = b"#INRIMAGE-4#{\nXDIM=256\nYDIM=256\nZDIM=256\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 bits\nCPU=decm\n"
head = head.ljust(252, b"\n") + b"##}\n"
zeros = gzip.compress(bytes(1 << 20), 9)
with open(sys.argv[1], "wb") as f:
    f.write(gzip.compress(head, 9))
    for _ in range(1024):
        f.write(zeros)
PY
declared_kib=$((16 * 1024))
check "gzip bomb (16 MiB declared, 1 GiB inflated)" $((declared_kib + 64 * 1024)) inr "$work/bomb.inr.gz" 0

ln -s /dev/zero "$work/zero.off"
cap=$((64 << 20))
check "/dev/zero as .off, 64 MiB input limit" $((64 * 1024 + 64 * 1024)) mesh "$work/zero.off" "$cap"
exit $status
