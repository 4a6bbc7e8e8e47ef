#!/usr/bin/env python3
"""Peers for bench/delaunay/run.sh: writes the shared point files, and times Triangle (PyPI
`triangle`) and scipy.spatial.Delaunay (qhull) on them, one library and size per process so
that the reported peak memory belongs to that run alone.

  peers.py write DIR N...          write DIR/points_N.bin (float64 x, y pairs, seed 42)
  peers.py run LIB DIR N REPEATS   print one JSON line: lib, n, cpu_ms (median), wall_ms, peak_rss_mb, triangles
"""
import json
import resource
import statistics
import sys
import time

import numpy as np


def points(directory, n):
    return np.fromfile(f"{directory}/points_{n}.bin", dtype=np.float64).reshape(-1, 2)


def main():
    if sys.argv[1] == "write":
        directory = sys.argv[2]
        for n in map(int, sys.argv[3:]):
            rng = np.random.default_rng(42)
            rng.random((n, 2)).astype(np.float64).tofile(f"{directory}/points_{n}.bin")
        return
    _, _, lib, directory, n, repeats = sys.argv
    n, repeats = int(n), int(repeats)
    pts = points(directory, n)
    if lib == "triangle":
        import triangle

        def run():
            # Default switches: the Delaunay triangulation of the vertices (divide and conquer).
            return len(triangle.triangulate({"vertices": pts}, "Q")["triangles"])
    elif lib == "scipy":
        from scipy.spatial import Delaunay

        def run():
            return len(Delaunay(pts).simplices)
    else:
        raise SystemExit(f"unknown library {lib}")
    cpu, wall = [], []
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        triangles = run()
        cpu.append((time.process_time() - c0) * 1e3)
        wall.append((time.perf_counter() - w0) * 1e3)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(json.dumps({"lib": lib, "n": n, "cpu_ms": statistics.median(cpu), "wall_ms": statistics.median(wall),
                      "peak_rss_mb": peak, "triangles": triangles}))


if __name__ == "__main__":
    main()
