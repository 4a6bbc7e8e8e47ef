#!/usr/bin/env bash
# Polygon triangulation: triangulate_faces of a ~1M-quad torus and of jagged polygons, hmira on
# halfedge_mesh, CGAL and OpenMesh beside CGAL's triangulate_faces and OpenMesh's triangulate;
# median CPU ratios at the end.
# Five repetitions of each case; the ratios at the end are of median CPU times.
#   bench/triangulation/run.sh [Google Benchmark options, e.g. --benchmark_filter=REGEX]
set -euo pipefail
exec bash "$(dirname "$0")/../support/run_family.sh" triangulation_bench bench/triangulation/triangulation_bench "$@"
