#!/usr/bin/env bash
# Hole filling: fill_hole on halfedge_mesh and on CGAL's Surface_mesh beside CGAL's
# triangulate_hole (Liepa, no Delaunay) on 40 holes cut into bunny00, and refine + fair beside
# triangulate_refine_and_fair_hole; patch areas side by side.
# Five repetitions; Google Benchmark prints each case's mean, median and spread.
#   bench/holes/run.sh [Google Benchmark options, e.g. --benchmark_filter=REGEX]
set -euo pipefail
exec bash "$(dirname "$0")/../support/run_family.sh" holes_bench bench/holes/holes_bench --benchmark_report_aggregates_only=true "$@"
