#!/usr/bin/env bash
# Decimation to 1% of the twice-Loop-subdivided bunny: hmira (halfedge_mesh, OpenMesh, CGAL)
# against CGAL's Garland-Heckbert edge_collapse, OpenMesh's Decimater + ModQuadricT and Open3D's
# simplify_quadric_decimation, in one run; prints times and ratios, and leaves every output mesh
# in $HMIRA_DECIMATION_OUT (default build-bench/decimation-out) for the quality tool.
# Usage: bench/decimation/run.sh [REPS]   (HMIRA_BENCH_VENV selects the peers' venv)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HMIRA_BENCH_BUILD:-$root/build-bench}"
reps="${1:-3}"
out="${HMIRA_DECIMATION_OUT:-$build/decimation-out}"
py="$(bash "$root/scripts/bench-venv.sh")"
data="${HMIRA_TEST_DATA:-$root/build/test-data}"
[ -f "$data/meshes/bunny00.off" ] || "$root/scripts/test-data.sh" "$data" >/dev/null
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target decimation_bench -j2 >/dev/null
mkdir -p "$out"
"$build/bench/decimation/decimation_bench" --bunny "$data/meshes/bunny00.off" --out "$out" --reps "$reps" | tee "$out/hmira.txt"
target="$(sed -n 's/^input .* target \([0-9]*\)$/\1/p' "$out/hmira.txt")"
"$py" "$root/bench/decimation/peers.py" "$out" "$target" "$reps" | tee "$out/open3d.txt"
read -r wall cpu < <(sed -n 's/^hmira_halfedge_seconds //p' "$out/hmira.txt")
read -r o3wall o3cpu < <(awk '{print $2, $5}' "$out/open3d.txt")
awk -v w="$wall" -v c="$cpu" -v ow="$o3wall" -v oc="$o3cpu" \
  'BEGIN { printf "  hmira halfedge_mesh / open3d                   %.3f  %.3f\n", w / ow, c / oc }'
echo "output meshes in $out"
