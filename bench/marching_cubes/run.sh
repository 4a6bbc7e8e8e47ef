#!/usr/bin/env bash
# Marching cubes, hmira against vtkFlyingEdges3D, vtkMarchingCubes, scikit-image and PyMCubes,
# in one run on the same volumes and thread counts. Usage (from anywhere):
#   bench/marching_cubes/run.sh            # builds into build-bench, prints markdown tables (wall, then CPU,
#                                          # then memory bandwidth against the 384^3 cases)
# Needs scripts/install-deps.sh to have run; creates the peers' venv and test data itself.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HMIRA_BENCH_BUILD:-$root/build-bench}"
py="$(bash "$root/scripts/bench-venv.sh")"   # creates the peers' venv on first use
"$root/scripts/test-data.sh" "$root/build/test-data" >/dev/null
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target bench_marching_cubes bandwidth_probe -j2 >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export HMIRA_TEST_DATA="$root/build/test-data"
"$build/bench/marching_cubes/bench_marching_cubes" --export "$work/volumes"
"$py" "$root/bench/marching_cubes/peers.py" "$work/volumes" "$build/bench/marching_cubes/bench_marching_cubes" 1 2
# The same volumes against vtkFlyingEdges3D in CPU time (all threads), medians of 7: on a shared
# machine the wall times above mostly measure the other processes.
"$py" "$root/bench/marching_cubes/cpu_side_by_side.py" "$work/volumes" "$build/bench/marching_cubes/bench_marching_cubes" 7 1 2 2>/dev/null
# Memory bandwidth on this machine (bandwidth_probe: read, first-touch write, touched
# write at 1 and 2 threads) against hmira's and vtkFlyingEdges3D's 1 -> 2 thread speed-ups at 384^3.
echo
echo "## Memory bandwidth and the 384^3 speed-ups (bandwidth_probe, bandwidth.py)"
"$py" "$root/bench/marching_cubes/bandwidth.py" "$work/volumes" "$build/bench/marching_cubes/bench_marching_cubes" \
  "$build/bench/marching_cubes/bandwidth_probe" 5
