#!/usr/bin/env bash
# Decimation to 1% of the twice-Loop-subdivided bunny: hmira (halfedge_mesh, OpenMesh, CGAL)
# against CGAL's Garland-Heckbert edge_collapse and OpenMesh's Decimater + ModQuadricT in C++; then
# from Python (peers.py) against pyfqmr, fast-simplification, Open3D and pymeshlab on armadillo
# Loop x2, bunny00, fandisk and elephant at 1% and 10%. Prints times, quality and ratios, and leaves
# every output mesh in $HMIRA_DECIMATION_OUT (default build-bench/decimation-out).
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
# The Python peers (pyfqmr, fast-simplification, Open3D, pymeshlab) beside hmira's package, installed
# from this tree into the venv first: times of the call alone, Hausdorff, minimum angles, ratios.
"$py" -m pip install -q pyfqmr fast-simplification pymeshlab nanobind scikit-build-core >&2
CMAKE_BUILD_PARALLEL_LEVEL=2 "$py" -m pip install -q --no-build-isolation "$root" >&2
"$py" "$root/bench/decimation/peers.py" "$data" --reps "${HMIRA_DECIMATION_REPS:-5}" --out "$out/python" | tee "$out/peers.txt"
echo "output meshes in $out"
