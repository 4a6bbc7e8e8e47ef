#!/usr/bin/env bash
# Builds bench_core, extracts the real meshes, and prints hmira beside OpenMesh and CGAL:
# first the interleaved-pair table (median of >= 10 pairs, ratio = hmira / peer), then, with
# --full, every Google Benchmark workload (adapters, winged-edge, face-vertex included).
# Times are CPU medians (the machine may be shared). --workload and --mesh keep only the pairs
# of one workload (build, one_ring, flip) and of meshes whose name contains the text.
#   bench/core/run.sh [--rounds N] [--workload W] [--mesh TEXT] [--full] [--build-dir DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench-core"
rounds=11
full=0
workload=""
mesh=""
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds="$2"; shift 2 ;;
    --full) full=1; shift ;;
    --workload) workload="$2"; shift 2 ;;
    --mesh) mesh="$2"; shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    *) echo "usage: $0 [--rounds N] [--workload W] [--mesh TEXT] [--full] [--build-dir DIR]" >&2; exit 2 ;;
  esac
done
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
  -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target bench_core -j2
"$root/scripts/test-data.sh" "$build/test-data" || echo "run.sh: no real meshes; bench_core falls back to a grid" >&2
export HMIRA_TEST_DATA="$build/test-data"
echo "== interleaved pairs: $rounds rounds each, median of per-round ratios (hmira / peer) =="
"$build/bench/core/bench_core" --pairs "$rounds" "$workload" "$mesh"
if [ "$full" = 1 ]; then
  echo "== Google Benchmark: every workload =="
  "$build/bench/core/bench_core" --benchmark_min_time=0.2
fi
