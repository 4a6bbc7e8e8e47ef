#!/usr/bin/env bash
# The Dask scale benchmark, by one command:
#   bench/dask/run.sh                 # 512^3 comparison, then the 1024^3 LocalCluster run
#   bench/dask/run.sh --part scale    # bench.py --help for the options
#   bench/dask/run.sh raw12g [GiB]    # `hmira mc` on a 12 GiB .raw, peak RSS by /usr/bin/time -v
# Uses the venv of scripts/python.sh (HMIRA_PY_VENV, default build/python-venv), which has
# hmira, dask, distributed and zarr; run scripts/python.sh first if it is missing.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ "${1:-}" = raw12g ]; then
  exec bash bench/dask/mc_raw_large.sh "${2:-12}"
fi
venv=${HMIRA_PY_VENV:-build/python-venv}
if ! "$venv/bin/python" -c "import hmira.dask, distributed" 2>/dev/null; then
  echo "no hmira.dask in $venv: run scripts/python.sh first (or set HMIRA_PY_VENV)" >&2
  exit 1
fi
echo "machine: $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB, load $(cut -d' ' -f1-3 /proc/loadavg)"
# The two parts in separate processes: a worker's getrusage peak would otherwise include the
# client's peak from the comparison (ru_maxrss survives fork and exec).
if [ $# -eq 0 ]; then
  "$venv/bin/python" bench/dask/bench.py --part compare
  exec "$venv/bin/python" bench/dask/bench.py --part scale
fi
exec "$venv/bin/python" bench/dask/bench.py "$@"
