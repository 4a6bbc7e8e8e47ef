#!/usr/bin/env bash
# Booleans side by side, one run, same inputs: Manifold and libigl from Python (peers.py, which also
# makes the inputs) and CGAL's corefinement in C++ (boolean_bench). Each tool twice: with all
# threads, and pinned to one core (taskset -c 0; manifold3d has no thread setting of its own;
# hmira is also told --threads 1 there).
# Usage: bench/boolean/run.sh [--quick] [--reps N]   (--quick: no 1M-triangle spheres)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${HMIRA_BENCH_BUILD:-$root/build-bench}"
out="${HMIRA_BOOLEAN_OUT:-$build/boolean-out}"
py="$(bash "$root/scripts/bench-venv.sh")"
"$py" -m pip install -q manifold3d libigl >&2
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target boolean_bench -j2 >/dev/null
echo "== all threads ($(nproc) cores)"
"$py" "$root/bench/boolean/peers.py" --out "$out" --cgal "$build/bench/boolean/boolean_bench" "$@"
echo "== one core (taskset -c 0)"
taskset -c 0 "$py" "$root/bench/boolean/peers.py" --out "$out" --cgal "$build/bench/boolean/boolean_bench" \
    --threads 1 "$@"
