#!/usr/bin/env bash
# Builds the parser fuzz targets (OBJ, OFF, PLY, STL, glTF, VTK, 3MF, INR plain and gzip, binvox, .xyz/.csv
# points) with clang 14's libFuzzer (+ ASan/UBSan) and runs each for a bounded time with its
# dictionary on a copy of its committed corpus, so CI stays deterministic in what it keeps.
# 11 targets x 18 s (scripts/test.sh) keeps the CI run near 3.5 minutes; fuzz/run-long.sh runs
# them for long.
# First checks that every public header under include/hmira/io and include/hmira/meshes
# compiles on its own with clang 14 (-Wall -Wextra -Werror).
# Usage: fuzz/run.sh [seconds per target, default 18] [build folder, default build-fuzz]
# Needs clang-14, libclang-rt-14-dev and zlib1g-dev (scripts/install-deps.sh). Exits non-zero on a finding
# or on a header that does not compile.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
seconds="${1:-18}"
out="${2:-$root/build-fuzz}"
cxx="${CXX_FUZZ:-clang++-14}"
command -v "$cxx" >/dev/null || { echo "fuzz: $cxx not found (apt install clang-14 libclang-rt-14-dev)" >&2; exit 2; }
mkdir -p "$out"
status=0

# The I/O headers, and the meshes users read into, compile with clang 14. One small
# translation unit per public header (detail/ excluded), generated here; a mesh header's TU
# also instantiates its mesh class explicitly, so that every member (ranges included) is
# compiled, not only the declarations.
header_cxx="${CXX_HEADER_CHECK:-clang++-14}"
command -v "$header_cxx" >/dev/null || { echo "fuzz: $header_cxx not found (apt install clang-14)" >&2; exit 2; }
tus="$out/header-check"
rm -rf "$tus"; mkdir -p "$tus"
jobs="${HMIRA_FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}"
check_header() {  # check_header HEADER: one syntax-only TU; prints the header's name on failure
  local header="$1" tu
  tu="$tus/$(echo "$header" | tr '/.' '__').cpp"
  echo "#include <$header>" > "$tu"
  sed -n 's/^class \(basic_[a-z_]*_mesh\)[ :{].*$/template class hmira::\1<double>;/p' "$root/include/$header" >> "$tu"
  if ! "$header_cxx" -std=c++20 -Wall -Wextra -Werror -fsyntax-only -I"$root/include" "$tu" > "$tu.log" 2>&1; then
    echo "fuzz: $header does not compile with $header_cxx:" >&2
    grep -m 10 -E "error:" "$tu.log" >&2 || head -10 "$tu.log" >&2
    echo "$header" > "$tu.failed"
  fi
}
export -f check_header; export tus root header_cxx
(cd "$root/include" && find hmira/io hmira/meshes -name '*.hpp' -not -path '*/detail/*' | sort) > "$tus/list"
headers=$(wc -l < "$tus/list")
xargs -P "$jobs" -I{} bash -c 'check_header "$1"' _ {} < "$tus/list"
failed=$(find "$tus" -name '*.failed' | wc -l)
if [ "$headers" -eq 0 ]; then echo "fuzz: no headers found to check" >&2; status=1; fi
if [ "$failed" -ne 0 ]; then status=1; fi
echo "fuzz: header check: $((headers - failed)) of $headers headers compile with $header_cxx -std=c++20 -Wall -Wextra -Werror"

# Every target: the mesh parsers (fuzz_io.hpp) and the volume and point readers
# (fuzz_volume.hpp), each with its keyword dictionary (dict/<target>.dict) and a copy of its
# committed corpus (corpus/<target>/), which holds the reproducers of known hostile inputs.
targets="obj off ply stl gltf inr inr_gz binvox points vtk 3mf"
build_target() {  # build_target NAME: (re)builds $out/fuzz_NAME when a source is newer
  local bin="$out/fuzz_$1"
  if [ ! -x "$bin" ] || [ "$here/fuzz_$1.cpp" -nt "$bin" ] || \
     [ -n "$(find "$root/include/hmira" "$here/fuzz_io.hpp" "$here/fuzz_volume.hpp" -newer "$bin" -print -quit)" ]; then
    echo "fuzz: building $bin"
    "$cxx" -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
      -DHMIRA_HAS_ZLIB=1 -I"$root/include" "$here/fuzz_$1.cpp" -o "$bin" -lz
  fi
}
# Build all targets first, $jobs at a time (each is one clang process).
pids=()
for fmt in $targets; do
  build_target "$fmt" > "$out/build_$fmt.log" 2>&1 &
  pids+=($!)
  if [ "${#pids[@]}" -ge "$jobs" ]; then wait "${pids[0]}" || status=1; pids=("${pids[@]:1}"); fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
for fmt in $targets; do
  [ -x "$out/fuzz_$fmt" ] || { echo "fuzz: $fmt did not build:" >&2; cat "$out/build_$fmt.log" >&2; exit 1; }
done
if [ "${HMIRA_FUZZ_ONLY_BUILD:-0}" = 1 ]; then exit $status; fi

run_target() {  # run_target NAME: fuzzes one target on a fresh copy of its committed corpus
  local fmt="$1" bin="$out/fuzz_$1" work="$out/corpus-$1"
  rm -rf "$work" "$out/artifacts-$fmt"; mkdir -p "$work" "$out/artifacts-$fmt"
  cp "$here/corpus/$fmt/"* "$work/"
  if ! "$bin" -seed="${HMIRA_FUZZ_SEED:-1}" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 -timeout=10 \
        -dict="$here/dict/$fmt.dict" -artifact_prefix="$out/artifacts-$fmt/" -print_final_stats=1 "$work" > "$out/fuzz_$fmt.log" 2>&1; then
    echo "fuzz: $fmt FAILED, see $out/fuzz_$fmt.log and $out/artifacts-$fmt/" >&2
    tail -30 "$out/fuzz_$fmt.log" >&2
    return 1
  fi
  grep -E "stat::number_of_executed_units|cov:" "$out/fuzz_$fmt.log" | tail -2 | sed "s/^/fuzz: $fmt: /"
}
# $jobs targets at a time, each for $seconds.
echo "fuzz: $(echo $targets | wc -w) targets for ${seconds}s each, $jobs at a time"
pids=()
for fmt in $targets; do
  run_target "$fmt" &
  pids+=($!)
  if [ "${#pids[@]}" -ge "$jobs" ]; then wait "${pids[0]}" || status=1; pids=("${pids[@]:1}"); fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit $status
