#!/usr/bin/env bash
# Isotropic remeshing against CGAL: builds remeshing_bench (Release, benchmarks on)
# and runs it on real meshes from scripts/test-data.sh; each run prints times, the ratios
# against the targets and the quality of every output. Usage: bench/remeshing/run.sh [build-dir]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build-bench}"
data="${HMIRA_TEST_DATA:-/work/test-data}/meshes"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON >/dev/null
fi
cmake --build "$build" --target remeshing_bench mesh_quality
for mesh in bunny00 elephant; do
  "$build/bench/remeshing/remeshing_bench" "$data/$mesh.off" -k 5
done
"$build/bench/remeshing/remeshing_bench" "$data/fandisk.off" -k 5 --features 45
