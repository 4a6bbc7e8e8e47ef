"""hmira's Python package against what numpy users run today, in one process and one run:
marching cubes vs scikit-image, voxelization vs trimesh (voxelized().fill()) and Open3D,
Delaunay vs scipy.spatial.Delaunay and Triangle, mesh reading vs trimesh.load and meshio.
Each line gives the best of `repeats` times, the ratio hmira / peer (below 1: hmira faster),
and for hmira the Python call's overhead over the C++ time of the same work (measured inside
the extension). Peers that are not installed are reported as missing, not skipped silently."""
import argparse
import os
import tempfile
import time

import numpy as np

import hmira
from hmira import _core


def best(fn, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
        del out  # freeing the result is not part of the call (nor of the C++ time)
    return min(times)


def best_with_cpp(fn, repeats):
    runs = []
    for _ in range(repeats):
        start = time.perf_counter()
        out = fn()
        runs.append((time.perf_counter() - start, _core._last_cpp_seconds()))
        del out
    return min(runs)


def report(name, ours, cpp, peers):
    line = f"{name:<34} hmira {ours * 1e3:9.1f} ms  (C++ {cpp * 1e3:9.1f} ms, Python overhead x{ours / cpp:5.3f})"
    print(line)
    for peer, t in peers.items():
        if t is None:
            print(f"{'':<34} {peer:<28} not installed")
        else:
            print(f"{'':<34} {peer:<28} {t * 1e3:9.1f} ms   hmira/peer {ours / t:7.4f}")


def optional(module):
    try:
        return __import__(module, fromlist=["_"])
    except ImportError:
        return None


def sphere_volume(n):
    ax = np.linspace(-1.0, 1.0, n, dtype=np.float32)
    x, y, z = np.meshgrid(ax, ax, ax, indexing="ij", sparse=True)
    return np.sqrt(x * x + y * y + z * z) - np.float32(0.8)


def bench_marching_cubes(n, repeats):
    vol = np.ascontiguousarray(sphere_volume(n))
    measure = optional("skimage.measure")
    for threads in (1, 0):
        ours, cpp = best_with_cpp(lambda: hmira.marching_cubes(vol, 0.0, threads=threads), repeats)
        peers = {"skimage.marching_cubes": best(lambda: measure.marching_cubes(vol, 0.0), repeats) if measure and threads == 1 else None}
        if threads != 1:
            peers = {}
        report(f"marching cubes {n}^3 threads={threads or 'all'}", ours, cpp, peers)


def bench_voxelize(resolution, repeats):
    v, f = hmira.marching_cubes(sphere_volume(192), 0.0)
    trimesh = optional("trimesh")
    o3d = optional("open3d")
    for threads in (1, 0):
        ours, cpp = best_with_cpp(lambda: hmira.voxelize(v, f, resolution=resolution, threads=threads), repeats)
        peers = {}
        if threads == 1:
            tm = trimesh.Trimesh(v, f, process=False) if trimesh else None
            pitch = (v.max(0) - v.min(0)).max() / resolution
            peers["trimesh voxelized().fill()"] = best(lambda: tm.voxelized(pitch).fill(), 1) if tm is not None else None
            if o3d is not None:
                m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(v), o3d.utility.Vector3iVector(f))
                peers["open3d (surface)"] = best(lambda: o3d.geometry.VoxelGrid.create_from_triangle_mesh(m, pitch), repeats)
            else:
                peers["open3d (surface)"] = None
        report(f"voxelize {len(f)} tris res={resolution} threads={threads or 'all'}", ours, cpp, peers)


def bench_delaunay(n, repeats):
    p = np.random.default_rng(0).random((n, 2))
    spatial = optional("scipy.spatial")
    triangle = optional("triangle")
    ours, cpp = best_with_cpp(lambda: hmira.delaunay_triangulation(p), repeats)
    peers = {"scipy.spatial.Delaunay": best(lambda: spatial.Delaunay(p), repeats) if spatial else None,
             "triangle.triangulate": best(lambda: triangle.triangulate({"vertices": p}), repeats) if triangle else None}
    report(f"delaunay {n} points", ours, cpp, peers)


def bench_read(triangles, repeats):
    n = int(np.sqrt(triangles / 4.4)) + 1  # sphere surfaces hold about 4.4 n^2 triangles at n^3
    v, f = hmira.marching_cubes(sphere_volume(n), 0.0)
    trimesh = optional("trimesh")
    meshio = optional("meshio")
    with tempfile.TemporaryDirectory() as d:
        for fmt in ("ply", "obj", "off"):
            path = os.path.join(d, f"m.{fmt}")
            hmira.write_mesh(path, (v, f))
            ours, cpp = best_with_cpp(lambda: hmira.read_mesh(path), repeats)
            peers = {"trimesh.load": best(lambda: trimesh.load(path, process=False), repeats) if trimesh else None,
                     "meshio.read": best(lambda: meshio.read(path), repeats) if meshio and fmt != "off" else None}
            report(f"read {fmt} {len(f)} triangles", ours, cpp, peers)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true", help="small sizes (a smoke test, not the issue's sizes)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--only", choices=["marching_cubes", "voxelize", "delaunay", "read"], help="one family")
    a = ap.parse_args()
    mc, vox, pts, tris = (96, 64, 20000, 100000) if a.quick else (384, 256, 1000000, 2000000)
    if a.only:
        globals()["bench_" + a.only]({"marching_cubes": mc, "voxelize": vox, "delaunay": pts, "read": tris}[a.only], a.repeats)
        return
    print(f"hmira {hmira.__version__}, {os.cpu_count()} cores; best of {a.repeats}")
    bench_marching_cubes(mc, a.repeats)
    bench_delaunay(pts, a.repeats)
    bench_read(tris, a.repeats)
    bench_voxelize(vox, a.repeats)


if __name__ == "__main__":
    main()
