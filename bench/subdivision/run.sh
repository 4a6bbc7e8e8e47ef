#!/usr/bin/env bash
# Builds subdivision_bench and runs it twice, printing each run's ratio tables (CPU, user and
# system time, medians):
#   1. as built: every case; hmira's large arrays ask for huge pages themselves (madvise, see
#      include/hmira/core/huge_pages.hpp), the peers' use 4 KiB pages;
#   2. with glibc's transparent-huge-page tunable (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), which
#      makes malloc madvise(MADV_HUGEPAGE) its large chunks: hmira and the peers alike, in one
#      process, so the comparison stays like-for-like. It measures what huge pages would save on
#      a machine whose /sys/kernel/mm/transparent_hugepage/enabled is [madvise]; with [always]
#      both runs use huge pages, with [never] neither does.
# At a million faces the kernel's faulting and zeroing of the output's fresh pages is about half
# the CPU time; run 2 shows how much of that is per-page overhead rather than zeroing.
# Each run ends with the target tables: the generic algorithm on OpenMesh and Surface_mesh / on
# halfedge_mesh, whole and less each model's up-front reserve (timed alone as
# <scheme>/reserve/<model>) or whole storage growth (reserve plus resize to the final counts,
# <scheme>/grow/<model>), with the fresh MB of the whole run and of that step alone; the load
# average is printed before and after each run.
# --interleave runs the repetitions of all cases in random order
# (--benchmark_enable_random_interleaving), so that on a loaded machine a busy spell is spread
# over every side instead of landing on one case's repetitions.
#   bench/subdivision/run.sh [--repetitions N] [--filter REGEX] [--build-dir DIR] [--no-huge-pages] [--interleave]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$root/build-bench-subdivision"
reps=5
filter='^(loop|catmull_clark)/'
huge=1
interleave=false
while [ $# -gt 0 ]; do
  case "$1" in
    --repetitions) reps="$2"; shift 2 ;;
    --filter) filter="$2"; shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    --no-huge-pages) huge=0; shift ;;
    --interleave) interleave=true; shift ;;
    *) echo "usage: $0 [--repetitions N] [--filter REGEX] [--build-dir DIR] [--no-huge-pages] [--interleave]" >&2; exit 2 ;;
  esac
done
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHMIRA_BUILD_BENCHMARKS=ON \
  -DHMIRA_BUILD_TESTS=OFF -DHMIRA_BUILD_APPS=OFF -DHMIRA_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target subdivision_bench -j2
bench="$build/bench/subdivision/subdivision_bench"
echo "transparent_hugepage/enabled: $(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null || echo unknown)"
echo "== as built (hmira advises huge pages for its large arrays; the peers use 4 KiB pages) =="
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
"$bench" --benchmark_filter="$filter" --benchmark_repetitions="$reps" --benchmark_enable_random_interleaving="$interleave" | sed -n '/^Median/,$p'
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "$huge" = 1 ]; then
  echo "== transparent huge pages for every large allocation (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) =="
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  GLIBC_TUNABLES=glibc.malloc.hugetlb=1 "$bench" --benchmark_filter="$filter" --benchmark_repetitions="$reps" --benchmark_enable_random_interleaving="$interleave" | sed -n '/^Median/,$p'
  echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
fi
