#!/usr/bin/env bash
# bench/delaunay/run.sh: Delaunay triangulation of 10^5, 10^6 and 4x10^6 uniform points,
# hmira against CGAL (C++, Google Benchmark), Triangle and scipy.spatial.Delaunay (Python venv),
# all on the same points in the same run. Prints CPU times (the machine is shared, so CPU time
# is the fair single-thread measure; wall time is printed too), ratios hmira/peer and peak RSS.
#   usage: bench/delaunay/run.sh [build-dir] [sizes...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-$root/build-delaunay-bench}"
shift || true
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(100000 1000000 4000000)
py="$(bash "$root/scripts/bench-venv.sh")"   # creates the peers' venv on first use
repeats=3

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
      -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" --target delaunay_bench -j2 >/dev/null

data="$build/delaunay-points"
mkdir -p "$data"
have_py=0
if [ -x "$py" ] && "$py" -c "import numpy, scipy, triangle" 2>/dev/null; then have_py=1; fi
if [ $have_py = 1 ]; then
  "$py" "$here/peers.py" write "$data" "${sizes[@]}"
else
  echo "note: the peers venv lacks numpy, scipy or triangle (scripts/bench-venv.sh); Triangle and scipy skipped," \
       "C++ benchmarks use their own points" >&2
fi

results="$build/delaunay-results.jsonl"
: > "$results"
bench="$build/bench/delaunay/delaunay_bench"
libs_cpp=$("$bench" --benchmark_list_tests | sed 's|/.*||' | sort -u)
for n in "${sizes[@]}"; do
  for lib in $libs_cpp; do
    # One process per case: its peak RSS is that case's alone.
    HMIRA_DELAUNAY_POINTS="$data" "$bench" --benchmark_filter="^$lib/$n/" --benchmark_repetitions=$repeats \
        --benchmark_report_aggregates_only=true --benchmark_format=json 2>/dev/null |
      python3 -c '
import json, sys
d = json.load(sys.stdin)
med = [b for b in d["benchmarks"] if b.get("aggregate_name") == "median"][0]
lib = med["run_name"].split("/")[0].replace("_delaunay", "")
n = int(med["run_name"].split("/")[1])
print(json.dumps({"lib": lib, "n": n, "cpu_ms": med["cpu_time"], "wall_ms": med["real_time"],
                  "peak_rss_mb": med["peak_rss_MB"], "triangles": med["triangles"]}))' >> "$results"
  done
  if [ $have_py = 1 ]; then
    for lib in triangle scipy; do
      "$py" "$here/peers.py" run "$lib" "$data" "$n" $repeats >> "$results"
    done
  fi
done

python3 - "$results" <<'PY'
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
by = {(r["lib"], r["n"]): r for r in rows}
libs = [l for l in ["hmira", "cgal", "triangle", "scipy"] if any(k[0] == l for k in by)]
sizes = sorted({r["n"] for r in rows})
print(f"\nDelaunay triangulation, uniform points in the unit square; median of runs; CPU ms (wall ms), peak RSS MB")
print(f"{'n':>9} | " + " | ".join(f"{l:>26}" for l in libs))
for n in sizes:
    cells = []
    for l in libs:
        r = by.get((l, n))
        cells.append(f"{r['cpu_ms']:8.1f} ({r['wall_ms']:7.1f}) {r['peak_rss_mb']:6.0f}MB" if r else f"{'-':>26}")
    print(f"{n:>9} | " + " | ".join(cells))
print(f"\nratio hmira/peer (CPU time; < 1 means hmira is faster)")
print(f"{'n':>9} | " + " | ".join(f"{l:>9}" for l in libs if l != "hmira"))
for n in sizes:
    h = by.get(("hmira", n))
    cells = []
    for l in libs:
        if l == "hmira":
            continue
        r = by.get((l, n))
        cells.append(f"{h['cpu_ms'] / r['cpu_ms']:9.2f}" if h and r else f"{'-':>9}")
    print(f"{n:>9} | " + " | ".join(cells))
tri = {(r["lib"], r["n"]): int(r["triangles"]) for r in rows}
for n in sizes:
    counts = {l: tri[(l, n)] for l in libs if (l, n) in tri}
    if len(set(counts.values())) > 1:
        print(f"warning: triangle counts differ at n={n}: {counts}")
PY
