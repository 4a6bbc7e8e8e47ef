#!/usr/bin/env bash
# Smoothing: ten uniform Laplacian steps on a ~1M-triangle torus, hmira on halfedge_mesh and on
# OpenMesh beside OpenMesh's JacobiLaplaceSmootherT, and Taubin beside CGAL's
# angle_and_area_smoothing; median CPU ratios at the end. Five repetitions of each case.
# Then the Python peers (peers.py): trimesh's filter_laplacian and filter_taubin on bunny00 and
# armadillo Loop x2, hmira at 1 and 2 threads, and Mesh(V, F) beside Open3D, pyfqmr and trimesh,
# in the benchmark venv (scripts/bench-venv.sh) with this tree's hmira installed by pip;
# HMIRA_BENCH_NO_PYTHON=1 skips them.
#   bench/smoothing/run.sh [Google Benchmark options, e.g. --benchmark_filter=REGEX]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
bash "$here/../support/run_family.sh" smoothing_bench bench/smoothing/smoothing_bench "$@"
if [ "${HMIRA_BENCH_NO_PYTHON:-0}" != 1 ]; then
  py=$(bash "$root/scripts/bench-venv.sh")
  "$py" -m pip install -q "$root"
  "$py" "$here/peers.py" --data "${HMIRA_TEST_DATA:-$root/build/test-data}"
fi
