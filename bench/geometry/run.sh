#!/usr/bin/env bash
# vertex_normals: hmira (on its own meshes and, through the interop traits, on OpenMesh's and
# CGAL's meshes) against OpenMesh's update_face_normals + update_vertex_normals and CGAL's
# Polygon_mesh_processing::compute_vertex_normals on the same torus. Prints a markdown table of
# times and ratios (peer time / hmira time: above 1 means hmira is faster). Usage:
#   bench/geometry/run.sh            # builds into build-bench (HMIRA_BENCH_BUILD overrides)
# Needs scripts/install-deps.sh to have run (Google Benchmark, OpenMesh, CGAL).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HMIRA_BENCH_BUILD:-$root/build-bench}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target bench_vertex_normals -j2 >/dev/null
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$build/bench/geometry/bench_vertex_normals" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_out="$work/result.json" --benchmark_out_format=json >&2
python3 - "$work/result.json" <<'PY'
import json, sys
runs = {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    name = b["run_name"]                     # library/mesh/variant/n
    lib, mesh, variant, n = name.split("/")
    runs[(lib, mesh, variant, int(n))] = b["real_time"]  # milliseconds
sizes = sorted({k[3] for k in runs})
peers = {"openmesh": ("openmesh", "openmesh", "face_and_vertex_normals"),
         "cgal": ("cgal", "cgal", "compute_vertex_normals")}
print("| torus | hmira on | weighting | hmira (ms) | peer | peer (ms) | peer / hmira |")
print("|---|---|---|---:|---|---:|---:|")
for n in sizes:
    for mesh, peer in peers.items():
        p = runs.get(peer + (n,))
        for variant in ("area", "angle"):
            h = runs.get(("hmira", mesh, variant, n))
            if h is None or p is None:
                continue
            print(f"| {n}x{n} ({2*n*n} tris) | {mesh} | {variant} | {h:.2f} | {peer[0]} {peer[2]} | {p:.2f} | {p/h:.2f} |")
    for mesh in ("face_vertex_mesh", "halfedge_mesh"):
        for variant in ("area", "angle"):
            h = runs.get(("hmira", mesh, variant, n))
            if h is not None:
                print(f"| {n}x{n} ({2*n*n} tris) | {mesh} | {variant} | {h:.2f} | | | |")
if not runs:
    sys.exit("run.sh: no benchmark results")
PY
