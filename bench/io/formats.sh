#!/usr/bin/env bash
# Reading the 2M-triangle torus (bench/io) written by hmira as 3MF, VTP and GLB: hmira (C++
# read_soup and read_mesh into halfedge_mesh; Python hmira.read_mesh) beside trimesh
# (load(..., process=False): 3MF, GLB) and PyVista (read: VTP), in the same run, the readers
# alternated run by run, median wall time of the read call of N runs (default 5), each in a
# fresh process. ratio = peer / hmira (> 1: hmira is faster). Prints the load average.
#   bench/io/formats.sh [--data-dir DIR] [--runs N] [--python PY] [--hmira-path SITE]
# PY: a Python with trimesh, lxml, networkx and pyvista (default /work/venv-bench/bin/python);
# SITE: put first on PYTHONPATH for `import hmira` (a built wheel unpacked); without it the
# Python hmira column is left out.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
data="/tmp/hmira-io-bench"
runs=5
py="/work/venv-bench/bin/python"
site=""
while [ $# -gt 0 ]; do
  case "$1" in
    --data-dir) data="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --python) py="$2"; shift 2 ;;
    --hmira-path) site="$2"; shift 2 ;;
    *) echo "usage: $0 [--data-dir DIR] [--runs N] [--python PY] [--hmira-path SITE]" >&2; exit 2 ;;
  esac
done
bin="$data/formats_bench"
mkdir -p "$data"
if [ ! -x "$bin" ] || [ "$root/bench/io/formats_bench.cpp" -nt "$bin" ]; then
  "${CXX:-g++}" -std=c++20 -O2 -DNDEBUG -DHMIRA_HAS_ZLIB=1 -I"$root/include" "$root/bench/io/formats_bench.cpp" \
    -o "$bin" -lz
fi
[ -f "$data/torus_2M.3mf" ] || "$bin" --generate "$data" > /dev/null
peer_of() { case "$1" in vtp) echo pyvista ;; *) echo trimesh ;; esac; }
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-5s %12s %12s %12s %10s %12s %8s\n" format "hmira soup" "hmira mesh" "hmira py" peer "peer s" ratio
for ext in 3mf glb vtp; do
  f="$data/torus_2M.$ext"; peer=$(peer_of "$ext")
  : > "$data/$ext.soup"; : > "$data/$ext.mesh"; : > "$data/$ext.py"; : > "$data/$ext.peer"
  for ((i = 0; i < runs; ++i)); do
    read -r _ s _ m _ _ < <("$bin" --read "$f")
    echo "$s" >> "$data/$ext.soup"; echo "$m" >> "$data/$ext.mesh"
    "$py" "$root/bench/io/formats_peers.py" "$peer" "$f" | cut -d' ' -f1 >> "$data/$ext.peer"
    if [ -n "$site" ]; then
      PYTHONPATH="$site" "$py" -W ignore "$root/bench/io/formats_peers.py" hmira "$f" | cut -d' ' -f1 >> "$data/$ext.py"
    fi
  done
  s=$(median < "$data/$ext.soup"); m=$(median < "$data/$ext.mesh"); p=$(median < "$data/$ext.peer")
  h=$([ -n "$site" ] && median < "$data/$ext.py" || echo "-")
  printf "%-5s %12s %12s %12s %10s %12s %8.2f\n" "$ext" "$s" "$m" "$h" "$peer" "$p" "$(echo "$p / $s" | bc -l)"
done
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
