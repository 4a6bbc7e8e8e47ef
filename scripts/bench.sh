#!/usr/bin/env bash
# Runs every benchmark family side by side with its peers (C++ peers from Debian, Python peers
# from the venv that scripts/bench-venv.sh creates, which this script runs first) and prints each family's ratio table.
# Usage: bash scripts/bench.sh [family ...]     (default: all of bench/*/run.sh)
# Families: every bench/<family> with a run.sh (core euler io marching_cubes voxelize delaunay
# geometry subdivision smoothing triangulation holes decimation remeshing editing repair python
# dask sweep spatial boolean).
# sweep: size sweeps of the performance-critical algorithms (10^4 to 10^7 elements), the
# fitted log-log exponent of CPU time beside each doc block's complexity, PASS/FAIL; a few
# minutes (bench/sweep/run.sh --quick: under a minute). Not run in CI.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/test-data.sh build/test-data >/dev/null
# The families' run.sh scripts take the peers from this venv; create it here so that
# `bash scripts/bench.sh <family>` works on a fresh clone.
bash scripts/bench-venv.sh >/dev/null
families=("$@")
if [ ${#families[@]} -eq 0 ]; then
  for f in bench/*/run.sh; do families+=("$(basename "$(dirname "$f")")"); done
fi
status=0
for fam in "${families[@]}"; do
  if [ ! -f "bench/$fam/run.sh" ]; then
    echo "bench: no bench/$fam/run.sh" >&2
    status=1
    continue
  fi
  echo "================ $fam ================"
  bash "bench/$fam/run.sh" || { echo "bench: $fam failed" >&2; status=1; }
done
exit $status
