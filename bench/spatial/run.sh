#!/usr/bin/env bash
# Spatial queries (hmira.BVH) against Open3D's RaycastingScene and trimesh's proximity, in the
# benchmark venv (scripts/bench-venv.sh) with hmira installed by pip; trimesh uses rtree.
# Usage: bash bench/spatial/run.sh [--queries N] [--levels L] [--trimesh-subset N] [--repeats N]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
py=$(bash "$root/scripts/bench-venv.sh")
"$py" -m pip install -q rtree "$root"
"$py" "$root/bench/spatial/bench.py" "$@"
