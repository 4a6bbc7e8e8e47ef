#!/usr/bin/env bash
# Smoothing: ten uniform Laplacian steps on a ~1M-triangle torus, hmira on halfedge_mesh and on
# OpenMesh beside OpenMesh's JacobiLaplaceSmootherT, and Taubin beside CGAL's
# angle_and_area_smoothing; median CPU ratios at the end.
# Five repetitions of each case; the ratios at the end are of median CPU times.
#   bench/smoothing/run.sh [Google Benchmark options, e.g. --benchmark_filter=REGEX]
set -euo pipefail
exec bash "$(dirname "$0")/../support/run_family.sh" smoothing_bench bench/smoothing/smoothing_bench "$@"
