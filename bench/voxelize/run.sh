#!/usr/bin/env bash
# Solid voxelization, hmira against VTK vtkPolyDataToImageStencil, trimesh voxelized().fill()
# and Open3D's (surface-only) VoxelGrid, in one run with the same grids and thread counts:
#   bench/voxelize/run.sh            # builds into build-bench, prints a markdown table (CPU time)
# trimesh takes minutes on the big cases; HMIRA_BENCH_SKIP_TRIMESH_ABOVE=<triangles x res>
# skips it above that size (default 30000000: trimesh is skipped for the 2M-triangle mesh).
# HMIRA_BENCH_ROUNDS=N measures hmira and VTK N times in turn and takes each VTK ratio within
# its round (median of N): a machine whose speed drifts over minutes moves single-run ratios.
# HMIRA_BENCH_MESHES, HMIRA_BENCH_RESOLUTIONS and HMIRA_BENCH_VTK_ONLY narrow the run (peers.py).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HMIRA_BENCH_BUILD:-$root/build-bench}"
py="$(bash "$root/scripts/bench-venv.sh")"   # creates the peers' venv on first use
"$root/scripts/test-data.sh" "$root/build/test-data" >/dev/null
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target bench_voxelize -j2 >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export HMIRA_TEST_DATA="$root/build/test-data"
"$build/bench/voxelize/bench_voxelize" --export "$work/meshes"
"$py" "$root/bench/voxelize/peers.py" "$work/meshes" "$build/bench/voxelize/bench_voxelize" 1 2
