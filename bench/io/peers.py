#!/usr/bin/env python3
"""Python peers for bench/io: trimesh and Open3D reading the same files.

Prints one JSON line per (category, file, library) with the median CPU and wall time in ms
(5 repetitions after a warm-up, as bench_io's C++ readers):
  soup: indexed arrays  -- trimesh.load(process=False) (no welding, no merging)
  mesh: connected mesh  -- trimesh.load(process=True) (welds STL / merges vertices),
                           open3d.io.read_triangle_mesh (triangle mesh with adjacency-free arrays;
                           listed under soup as it builds no connectivity)
Each library runs in a fresh process of its own: Open3D timed right after trimesh had read the
same file was ~10% slower than alone, so sharing a process would flatter hmira.
"""
import json
import os
import statistics
import subprocess
import sys
import time


def median_times(fn, repeats):
    cpu, wall = [], []
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        out = fn()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
        del out
    return 1000 * statistics.median(cpu), 1000 * statistics.median(wall)


LIBRARIES = ("trimesh-soup", "trimesh-mesh", "open3d")


def load(which):
    """(category, display name, reader) for one library, or None if it is not installed."""
    try:
        if which.startswith("trimesh"):
            import trimesh
            process = which == "trimesh-mesh"
            return ("mesh" if process else "soup", f"trimesh(process={process})",
                    lambda p: trimesh.load(p, process=process, force="mesh"))
        import open3d as o3d
        o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
        return ("soup", "open3d", lambda p: o3d.io.read_triangle_mesh(p))
    except Exception as e:  # noqa: BLE001
        print(f"peers: {which} unavailable: {e}", file=sys.stderr)
        return None


def main(argv):
    if not argv or argv[0] != "--library":
        for which in LIBRARIES:
            subprocess.run([sys.executable, os.path.abspath(__file__), "--library", which, *argv], check=False)
        return
    lib = load(argv[1])
    libs = [lib] if lib else []
    paths = argv[2:]
    for p in paths:
        for cat, name, fn in libs:
            try:
                fn(p)  # warm-up, and skip formats a library cannot read
                cpu, wall = median_times(lambda: fn(p), 5)
            except Exception as e:  # noqa: BLE001
                print(f"peers: {name} cannot read {p}: {e}", file=sys.stderr)
                continue
            print(json.dumps({"category": cat, "file": os.path.basename(p), "library": name, "cpu_ms": cpu, "wall_ms": wall}), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
