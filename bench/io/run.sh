#!/usr/bin/env bash
# Reading mesh files: hmira beside OpenMesh, CGAL (C++, Google Benchmark) and trimesh, Open3D
# (Python venv), in the same run, like with like, and the ratio to the fastest peer.
#   soup = into indexed arrays: hmira read_soup | CGAL read_polygon_soup, tinyobjloader (OBJ, polygons
#          kept), trimesh process=False, Open3D
#   mesh = into a connected mesh (STL welded): hmira read_mesh into halfedge_mesh |
#          OpenMesh read_mesh (PolyMesh), CGAL read_polygon_mesh (Surface_mesh), trimesh process=True
# Times are the median process CPU time of 5 repetitions on both sides (CPU time is what a
# reader costs on a shared machine). ratio = fastest peer / hmira (> 1: hmira is faster).
#   bench/io/run.sh [--build-dir DIR] [--data-dir DIR] [--quick] [--only EXT]
# --only ply (obj, off, stl): read only the files with that extension, e.g. to time one reader.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench-io"
data="/tmp/hmira-io-bench"
quick=0
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --data-dir) data="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    --only) only="$2"; shift 2 ;;
    *) echo "usage: $0 [--build-dir DIR] [--data-dir DIR] [--quick] [--only EXT]" >&2; exit 2 ;;
  esac
done
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
  -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target bench_io -j2
bench="$build/bench/io/bench_io"
[ -f "$data/torus_2M.stl" ] || "$bench" --generate "$data" > /dev/null
"$root/scripts/test-data.sh" "$build/test-data" > /dev/null || true
files="$data/torus_2M.ply:$data/torus_2M.obj:$data/torus_2M.stl"
if [ "$quick" = 0 ]; then
  for m in refined_elephant.off bunny00.off sphere.ply pig.stl; do
    [ -f "$build/test-data/meshes/$m" ] && files="$files:$build/test-data/meshes/$m"
  done
fi
if [ -n "$only" ]; then
  kept=""
  for f in ${files//:/ }; do
    case "$f" in *."$only") kept="$kept${kept:+:}$f" ;; esac
  done
  [ -n "$kept" ] || { echo "bench/io: no file ends in .$only" >&2; exit 2; }
  files="$kept"
fi
out="$build/io-bench"
mkdir -p "$out"
echo "bench/io: C++ readers (hmira, OpenMesh, CGAL)..." >&2
HMIRA_IO_BENCH_FILES="$files" "$bench" --benchmark_format=json --benchmark_out="$out/cpp.json" --benchmark_out_format=json > /dev/null
echo "bench/io: Python readers (trimesh, Open3D)..." >&2
py="$(bash "$root/scripts/bench-venv.sh")"   # creates the peers' venv on first use
if [ -x "$py" ]; then
  "$py" "$root/bench/io/peers.py" ${files//:/ } > "$out/py.jsonl" 2> "$out/py.err" || true
else
  echo "bench/io: no $py (scripts/bench-venv.sh); Python peers skipped" >&2
  : > "$out/py.jsonl"
fi
python3 - "$out/cpp.json" "$out/py.jsonl" <<'PY'
import json, sys, collections
rows = collections.defaultdict(dict)  # (category, file) -> lib -> cpu ms
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    cat, f, lib = b["run_name"].split("/")[:3]
    rows[(cat, f)][lib] = b["cpu_time"]
for line in open(sys.argv[2]):
    if line.strip():
        r = json.loads(line)
        rows[(r["category"], r["file"])][r["library"]] = r["cpu_ms"]
print(f"{'work':5} {'file':22} {'hmira ms':>9}  {'fastest peer':24} {'peer ms':>9} {'ratio':>6}   all peers (ms)")
for (cat, f), libs in sorted(rows.items(), key=lambda kv: (kv[0][1], kv[0][0])):
    mine = libs.get("hmira" if cat == "soup" else "hmira_halfedge")
    peers = {k: v for k, v in libs.items() if not k.startswith("hmira")}
    if mine is None or not peers:
        continue
    fastest = min(peers, key=peers.get)
    extra = "  ".join(f"{k} {v:.1f}" for k, v in sorted(peers.items(), key=lambda kv: kv[1]))
    fv = libs.get("hmira_face_vertex")
    if fv is not None:
        extra += f"  | hmira face_vertex {fv:.1f}"
    print(f"{cat:5} {f:22} {mine:9.1f}  {fastest:24} {peers[fastest]:9.1f} {peers[fastest] / mine:6.2f}x  {extra}")
PY
