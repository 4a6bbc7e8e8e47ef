#!/usr/bin/env bash
# Python benchmark: hmira's package against scikit-image, trimesh, Open3D, scipy, Triangle and
# meshio, all in the benchmark venv (scripts/bench-venv.sh) with hmira installed by pip.
# Usage: bash bench/python/run.sh [--quick] [--repeats N]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
py=$(bash "$root/scripts/bench-venv.sh")
"$py" -m pip install -q meshio "$root"
"$py" "$root/bench/python/bench.py" "$@"
