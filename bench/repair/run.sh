#!/usr/bin/env bash
# Polygon-soup repair beside CGAL's (repair_polygon_soup + orient_polygon_soup +
# polygon_soup_to_polygon_mesh) on the libcgal-demo meshes CGAL's is_polygon_soup_a_polygon_mesh
# rejects, plus pig.stl: faces each kept and the time of each; then repair's size sweep (10k to
# 1M faces, time per corner).
#   bench/repair/run.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HMIRA_BENCH_BUILD:-$root/build-bench-repair}"
"$root/scripts/test-data.sh" "$root/build/test-data" > /dev/null
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
  -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target bench_repair_vs_cgal bench_repair_scaling -j2 > /dev/null
meshes="$root/build/test-data/meshes"
"$build/bench/repair/bench_repair_vs_cgal" "$meshes/pig.stl" "$meshes"
"$build/bench/repair/bench_repair_scaling" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
