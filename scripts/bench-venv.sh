#!/usr/bin/env bash
# Creates (once) the Python venv with the benchmark peers from PyPI, and prints its python.
# Usage: py=$(bash scripts/bench-venv.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="${HMIRA_BENCH_VENV:-$root/.venv-bench}"
if [ ! -x "$venv/bin/python" ] || [ ! -f "$venv/.complete" ]; then
  python3 -m venv "$venv" >&2
  "$venv/bin/pip" install -q --upgrade pip >&2
  "$venv/bin/pip" install -q numpy scipy scikit-image PyMCubes trimesh vtk open3d triangle >&2
  touch "$venv/.complete"
fi
echo "$venv/bin/python"
