#!/usr/bin/env bash
# Shared by the families whose benchmark is one Google Benchmark program with its peers compiled
# in (holes, smoothing, triangulation, editing): builds that target in Release and runs it with
# five repetitions, so that scripts/bench.sh runs every family.
#   bench/support/run_family.sh <target> <binary path under the build dir> [benchmark args...]
# HMIRA_BENCH_BUILD overrides the build directory (default build-bench-<target>).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
target="$1"; binary="$2"; shift 2
build="${HMIRA_BENCH_BUILD:-$root/build-bench-$target}"
"$root/scripts/test-data.sh" "$root/build/test-data" > /dev/null
export HMIRA_TEST_DATA="${HMIRA_TEST_DATA:-$root/build/test-data}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
  -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target "$target" -j2 > /dev/null
"$build/$binary" --benchmark_repetitions=5 "$@"
