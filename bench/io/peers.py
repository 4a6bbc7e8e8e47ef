#!/usr/bin/env python3
"""Python peers for bench/io: trimesh and Open3D reading the same files.

Prints one JSON line per (category, file, library) with the minimum CPU and wall time in ms:
  soup: indexed arrays  -- trimesh.load(process=False) (no welding, no merging)
  mesh: connected mesh  -- trimesh.load(process=True) (welds STL / merges vertices),
                           open3d.io.read_triangle_mesh (triangle mesh with adjacency-free arrays;
                           listed under soup as it builds no connectivity)
"""
import json
import os
import sys
import time


def best(fn, repeats):
    cpu, wall = [], []
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        out = fn()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
        del out
    return 1000 * min(cpu), 1000 * min(wall)


def main(paths):
    libs = []
    try:
        import trimesh
        libs.append(("soup", "trimesh(process=False)", lambda p: trimesh.load(p, process=False, force="mesh")))
        libs.append(("mesh", "trimesh(process=True)", lambda p: trimesh.load(p, process=True, force="mesh")))
    except Exception as e:  # noqa: BLE001
        print(f"peers: trimesh unavailable: {e}", file=sys.stderr)
    try:
        import open3d as o3d
        o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)
        libs.append(("soup", "open3d", lambda p: o3d.io.read_triangle_mesh(p)))
    except Exception as e:  # noqa: BLE001
        print(f"peers: open3d unavailable: {e}", file=sys.stderr)
    for p in paths:
        big = os.path.getsize(p) > (8 << 20)
        for cat, name, fn in libs:
            try:
                fn(p)  # warm-up, and skip formats a library cannot read
                cpu, wall = best(lambda: fn(p), 3 if big else 10)
            except Exception as e:  # noqa: BLE001
                print(f"peers: {name} cannot read {p}: {e}", file=sys.stderr)
                continue
            print(json.dumps({"category": cat, "file": os.path.basename(p), "library": name, "cpu_ms": cpu, "wall_ms": wall}), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
