#!/usr/bin/env bash
# Size sweeps: each performance-critical algorithm from 10^4 elements up to 10^7
# (the linear ones; less where time or memory do not allow, see bench/sweep/sweep_bench.cpp),
# the fitted exponent of CPU time against size beside the documented complexity, the spread of
# the time per element, each size's working set, and PASS/FAIL/UNSURE; then the editing sweeps
# (bench/editing's editing_scaling_bench, 10^4..10^6 faces). About ten minutes in all
# (decimation to 10^7 faces takes four); --quick: at most 10^6 (10^5 for remeshing), under a
# minute plus the build, and UNSURE where its largest decade crosses the last-level cache (the
# time per element steps up there for memory latency; the full sweep's largest decade lies
# beyond the cache and decides). Not run in CI.
#   bench/sweep/run.sh [--quick] [--only SUBSTRING] [--build-dir DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench-sweep"
args=()
quick=0
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; args+=(--quick); shift ;;
    --only) only="$2"; args+=(--only "$2"); shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    *) echo "usage: $0 [--quick] [--only SUBSTRING] [--build-dir DIR]" >&2; exit 2 ;;
  esac
done
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
  -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target sweep_bench editing_scaling_bench -j2
echo "== algorithm sweeps: median CPU time of 3 calls per size, fitted log-log exponent vs the doc block =="
"$build/bench/sweep/sweep_bench" "${args[@]}"
if [ -z "$only" ]; then
  echo "== editing sweeps (bench/editing/editing_scaling_bench) =="
  # "all" selects the whole-mesh edits and skips the gyroid comparison.
  "$build/bench/editing/editing_scaling_bench" "$([ "$quick" = 1 ] && echo 100000 || echo 1000000)" 3 all
fi
