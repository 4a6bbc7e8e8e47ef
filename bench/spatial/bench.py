"""Spatial queries against Open3D's RaycastingScene (Embree, float32) and trimesh's proximity:
armadillo.off Loop-subdivided twice, 10^6 query points uniform in its bounding box enlarged by
10%, 10^6 rays from them in uniformly random directions; all threads. Prints each time and the
ratio hmira / peer (below 1: hmira is faster), and checks that the answers agree.

Usage: python bench.py [--mesh PATH] [--levels 2] [--queries 1000000] [--trimesh-subset 2000]
"""
from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np

import hmira


def timed(f, repeats: int = 1):
    best, out = np.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main() -> None:
    ap = argparse.ArgumentParser()
    data = Path(os.environ.get("HMIRA_TEST_DATA", "/work/test-data")) / "meshes"
    ap.add_argument("--mesh", default=str(data / "armadillo.off"))
    ap.add_argument("--levels", type=int, default=2)
    ap.add_argument("--queries", type=int, default=1_000_000)
    ap.add_argument("--trimesh-subset", type=int, default=2000)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()

    m = hmira.read_mesh(a.mesh)
    m.subdivide(scheme="loop", levels=a.levels)
    v = np.array(m.vertices, dtype=np.float64)
    f = np.array(m.faces, dtype=np.int64)
    print(f"mesh: {Path(a.mesh).name} Loop x{a.levels}: {len(v)} vertices, {len(f)} triangles; "
          f"{a.queries} queries, {os.cpu_count()} cores")

    rng = np.random.default_rng(0)
    lo, hi = v.min(axis=0), v.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo) / 2 * 1.1
    points = rng.uniform(centre - half, centre + half, (a.queries, 3))
    dirs = rng.normal(size=(a.queries, 3))
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]

    rows = []

    t_build, bvh = timed(lambda: hmira.BVH(m), a.repeats)
    t_cp, (cp, cf, _, cd) = timed(lambda: bvh.closest_point(points), a.repeats)
    t_ray, (rt, rf, _, _) = timed(lambda: bvh.ray_intersect(points, dirs), a.repeats)
    t_any, hit_any = timed(lambda: bvh.ray_intersect(points, dirs, mode="any"), a.repeats)
    t_ray32, (rt32, _, _, _) = timed(
        lambda: bvh.ray_intersect(points.astype(np.float32), dirs.astype(np.float32)), a.repeats)

    try:
        import open3d as o3d

        v32, f32 = v.astype(np.float32), f.astype(np.uint32)
        p32 = points.astype(np.float32)
        rays32 = np.hstack([points, dirs]).astype(np.float32)

        def o3d_build():
            scene = o3d.t.geometry.RaycastingScene()
            scene.add_triangles(o3d.core.Tensor(v32), o3d.core.Tensor(f32))
            scene.compute_closest_points(o3d.core.Tensor(p32[:1]))  # the lazy build happens here
            return scene

        o_build, scene = timed(o3d_build, a.repeats)
        o_cp, ocp = timed(lambda: scene.compute_closest_points(o3d.core.Tensor(p32)), a.repeats)
        o_ray, oray = timed(lambda: scene.cast_rays(o3d.core.Tensor(rays32)), a.repeats)
        o_any, oocc = timed(lambda: scene.test_occlusions(o3d.core.Tensor(rays32)), a.repeats)
        od = np.linalg.norm(ocp["points"].numpy() - p32, axis=1)
        ot = oray["t_hit"].numpy()
        rows += [("build (add_triangles + first query)", t_build, "Open3D", o_build),
                 ("closest point", t_cp, "Open3D", o_cp),
                 ("first-hit rays", t_ray, "Open3D", o_ray),
                 ("first-hit rays (float32 input)", t_ray32, "Open3D", o_ray),
                 ("any-hit rays (occlusion)", t_any, "Open3D", o_any)]
        # Agreement (Open3D works in float32: differences of float rounding are expected).
        scale = float(np.linalg.norm(hi - lo))
        both = np.isfinite(ot) & np.isfinite(rt)
        print(f"agreement with Open3D: max |distance difference| / diagonal = {np.max(np.abs(od - cd)) / scale:.2e}; "
              f"hit/miss differ on {np.sum(np.isfinite(ot) != np.isfinite(rt))} of {a.queries} rays; "
              f"max |t difference| / diagonal on common hits = "
              f"{np.max(np.abs(ot[both] - rt[both])) / scale:.2e}; "
              f"occlusion differs on {np.sum(oocc.numpy().astype(bool) != hit_any)}")
    except ImportError as e:
        print(f"Open3D not available: {e}")

    try:
        import trimesh

        tm = trimesh.Trimesh(v, f, process=False)
        n = min(a.trimesh_subset, a.queries)
        sub = points[:n]
        tm_t, (tp, td, _) = timed(lambda: trimesh.proximity.closest_point(tm, sub), 1)
        h_t, _ = timed(lambda: bvh.closest_point(sub), a.repeats)
        rows.append((f"closest point, {n} queries (trimesh is slow)", h_t, "trimesh", tm_t))
        print(f"agreement with trimesh: max |distance difference| = {np.max(np.abs(td - cd[:n])):.2e}")
    except ImportError as e:
        print(f"trimesh not available: {e}")

    print(f"\n{'query':44s} {'hmira s':>9s} {'peer':>8s} {'peer s':>9s} {'ratio':>7s}")
    for name, h, peer, p in rows:
        print(f"{name:44s} {h:9.3f} {peer:>8s} {p:9.3f} {h / p:7.3g}x")


if __name__ == "__main__":
    main()
