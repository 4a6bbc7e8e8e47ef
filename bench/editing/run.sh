#!/usr/bin/env bash
# Editing: truncate, bevel and extrude on a ~1M-face torus, on halfedge_mesh and generically on
# CGAL and OpenMesh (bench/editing/editing_scaling_bench: the size sweep).
# Five repetitions; Google Benchmark prints each case's mean, median and spread.
#   bench/editing/run.sh [Google Benchmark options, e.g. --benchmark_filter=REGEX]
set -euo pipefail
exec bash "$(dirname "$0")/../support/run_family.sh" editing_bench bench/editing/editing_bench --benchmark_report_aggregates_only=true "$@"
