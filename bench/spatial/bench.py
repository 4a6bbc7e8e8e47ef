"""Spatial queries against Open3D's RaycastingScene (Embree, float32), libigl's signed_distance
(fast winding number and hierarchical winding number signs) and trimesh's proximity:
armadillo.off Loop-subdivided twice, 10^6 query points uniform in its bounding box enlarged by
10%, 10^6 rays from them in uniformly random directions; all threads. Prints each time and the
ratio hmira / peer (below 1: hmira is faster), and checks that the answers agree. Then a sign
table: on an open hemisphere, two overlapping spheres as one soup and a sphere with flipped
faces, how many query points each method puts on the wrong side.

Usage: python bench.py [--mesh PATH] [--levels 2] [--queries 1000000] [--trimesh-subset 2000]
                       [--igl-subset 100000] [--igl-wn-subset 2000] [--no-signs]
"""
from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

import numpy as np

import hmira


def timed(f, repeats: int = 1):
    """The median wall time of `repeats` calls, and the last call's result."""
    times, out = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), out


def alternated(h, p, repeats: int):
    """hmira's call h and the peer's call p run in turns (h, p, h, p, ...), so that a change of
    load falls on both: (median time of h, h's result, median time of p, p's result)."""
    th, tp, oh, op = [], [], None, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        oh = h()
        th.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        op = p()
        tp.append(time.perf_counter() - t0)
    print(f"  hmira {np.median(th):.3f} s, peer {np.median(tp):.3f} s (load {os.getloadavg()[0]:.1f})", flush=True)
    return float(np.median(th)), oh, float(np.median(tp)), op


def main() -> None:
    ap = argparse.ArgumentParser()
    data = Path(os.environ.get("HMIRA_TEST_DATA", "/work/test-data")) / "meshes"
    ap.add_argument("--mesh", default=str(data / "armadillo.off"))
    ap.add_argument("--levels", type=int, default=2)
    ap.add_argument("--queries", type=int, default=1_000_000)
    ap.add_argument("--trimesh-subset", type=int, default=2000)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--igl-subset", type=int, default=100_000)
    ap.add_argument("--igl-wn-subset", type=int, default=2000)
    ap.add_argument("--no-signs", action="store_true")
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
    print(f"load average before: {os.getloadavg()}")
    bvh = hmira.BVH(m)
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

        # Each query type: hmira and Open3D in turns, medians of a.repeats runs each.
        t_build, bvh, o_build, scene = alternated(lambda: hmira.BVH(m), o3d_build, a.repeats)
        t_ray, (rt, rf, _, _), o_ray, oray = alternated(
            lambda: bvh.ray_intersect(points, dirs), lambda: scene.cast_rays(o3d.core.Tensor(rays32)), a.repeats)
        t_ray32, _, o_ray32, _ = alternated(
            lambda: bvh.ray_intersect(points.astype(np.float32), dirs.astype(np.float32)),
            lambda: scene.cast_rays(o3d.core.Tensor(rays32)), a.repeats)
        t_any, hit_any, o_any, oocc = alternated(
            lambda: bvh.ray_intersect(points, dirs, mode="any"),
            lambda: scene.test_occlusions(o3d.core.Tensor(rays32)), a.repeats)
        t_cp, (cp, cf, _, cd), o_cp, ocp = alternated(
            lambda: bvh.closest_point(points), lambda: scene.compute_closest_points(o3d.core.Tensor(p32)), a.repeats)
        t_sd, sd, o_sd, osd = alternated(
            lambda: hmira.signed_distance(v, f, points),
            lambda: scene.compute_signed_distance(o3d.core.Tensor(p32)), a.repeats)
        od = np.linalg.norm(ocp["points"].numpy() - p32, axis=1)
        ot = oray["t_hit"].numpy()
        rows += [("build (add_triangles + first query)", t_build, "Open3D", o_build),
                 ("closest point", t_cp, "Open3D", o_cp),
                 ("first-hit rays", t_ray, "Open3D", o_ray),
                 ("first-hit rays (float32 input)", t_ray32, "Open3D", o_ray32),
                 ("any-hit rays (occlusion)", t_any, "Open3D", o_any),
                 ("signed distance", t_sd, "Open3D", o_sd)]
        print(f"signed distance: the sign differs from Open3D's (ray parity) at "
              f"{np.sum(np.sign(osd.numpy()) != np.sign(sd))} of {a.queries} points")
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
        t_cp, (cp, cf, _, cd) = timed(lambda: bvh.closest_point(points), a.repeats)

    try:
        import trimesh

        if a.trimesh_subset <= 0:
            raise ImportError("skipped (--trimesh-subset 0)")
        tm = trimesh.Trimesh(v, f, process=False)
        n = min(a.trimesh_subset, a.queries)
        sub = points[:n]
        tm_t, (tp, td, _) = timed(lambda: trimesh.proximity.closest_point(tm, sub), 1)
        h_t, _ = timed(lambda: bvh.closest_point(sub), a.repeats)
        rows.append((f"closest point, {n} queries (trimesh is slow)", h_t, "trimesh", tm_t))
        print(f"agreement with trimesh: max |distance difference| = {np.max(np.abs(td - cd[:n])):.2e}")
    except ImportError as e:
        print(f"trimesh not available: {e}")

    try:
        import igl

        fi = np.ascontiguousarray(f, dtype=np.int64)
        for label, kind, n in [("fast winding number", igl.SIGNED_DISTANCE_TYPE_FAST_WINDING_NUMBER, a.igl_subset),
                               ("winding number", igl.SIGNED_DISTANCE_TYPE_WINDING_NUMBER, a.igl_wn_subset)]:
            n = min(n, a.queries)
            sub = np.ascontiguousarray(points[:n])
            h_t, hsd, i_t, (isd, _, _, _) = alternated(lambda: hmira.signed_distance(v, f, sub),
                                                       lambda: igl.signed_distance(sub, v, fi, kind), a.repeats)
            rows.append((f"signed distance, {n} queries", h_t, f"igl {label}", i_t))
            print(f"agreement with libigl ({label}): max |distance difference| = "
                  f"{np.max(np.abs(np.abs(isd) - np.abs(hsd))):.2e}; "
                  f"sign differs at {np.sum(np.sign(isd) != np.sign(hsd))}")
    except ImportError as e:
        print(f"libigl not available: {e}")

    print(f"\n{'query':44s} {'hmira s':>9s} {'peer':>8s} {'peer s':>9s} {'ratio':>7s}")
    for name, h, peer, p in rows:
        print(f"{name:44s} {h:9.3f} {peer:>8s} {p:9.3f} {h / p:7.3g}x")
    print(f"load average after: {os.getloadavg()}")
    if not a.no_signs:
        sign_table()


def sphere(centre=(0.0, 0.0, 0.0), subdivisions=4):
    import trimesh

    s = trimesh.creation.icosphere(subdivisions=subdivisions)
    return np.asarray(s.vertices) + np.asarray(centre), np.asarray(s.faces, dtype=np.int64)


def sign_cases():
    """(name, vertices, faces, points, truth): truth 1 inside, 0 outside; points near the
    surface, where the answer is a matter of convention, are left out."""
    rng = np.random.default_rng(1)
    cases = []
    # An open hemisphere (z >= 0): inside the dome above its rim, outside beyond the sphere.
    v, f = sphere()
    keep = np.all(v[f][:, :, 2] >= -1e-9, axis=1)
    p = rng.uniform(-1.5, 1.5, (20000, 3))
    r = np.linalg.norm(p, axis=1)
    inside, outside = (r < 0.9) & (p[:, 2] > 0.2), r > 1.1
    cases.append(("open hemisphere", v, f[keep], p[inside | outside], inside[inside | outside]))
    # Two overlapping spheres as one soup: inside either is inside.
    v1, f1 = sphere()
    v2, f2 = sphere((0.8, 0.0, 0.0))
    v, f = np.vstack([v1, v2]), np.vstack([f1, f2 + len(v1)])
    p = rng.uniform([-1.5, -1.5, -1.5], [2.3, 1.5, 1.5], (20000, 3))
    r1, r2 = np.linalg.norm(p, axis=1), np.linalg.norm(p - [0.8, 0, 0], axis=1)
    inside, outside = (r1 < 0.95) | (r2 < 0.95), (r1 > 1.05) & (r2 > 1.05)
    cases.append(("two overlapping spheres (soup)", v, f, p[inside | outside], inside[inside | outside]))
    # A sphere with a fifth of its faces flipped.
    v, f = sphere()
    f = f.copy()
    flip = rng.random(len(f)) < 0.2
    f[flip] = f[flip][:, ::-1]
    p = rng.uniform(-1.5, 1.5, (20000, 3))
    r = np.linalg.norm(p, axis=1)
    inside, outside = r < 0.95, r > 1.05
    cases.append(("sphere, 20% of faces flipped", v, f, p[inside | outside], inside[inside | outside]))
    return cases


def sign_table():
    """Wrong signs per method and case (a point counts wrong when the method puts it on the
    other side than the truth, or on the surface)."""
    methods = [(f"hmira {s}", lambda v, f, p, s=s: hmira.signed_distance(v, f, p, sign=s) < 0)
               for s in ("winding_number", "pseudo_normal", "parity")]
    try:
        import open3d as o3d

        def o3d_inside(v, f, p):
            scene = o3d.t.geometry.RaycastingScene()
            scene.add_triangles(o3d.core.Tensor(v.astype(np.float32)), o3d.core.Tensor(f.astype(np.uint32)))
            return scene.compute_signed_distance(o3d.core.Tensor(p.astype(np.float32))).numpy() < 0

        methods.append(("Open3D compute_signed_distance", o3d_inside))
    except ImportError:
        pass
    try:
        import igl

        for label, kind in [("fast winding number", igl.SIGNED_DISTANCE_TYPE_FAST_WINDING_NUMBER),
                            ("winding number", igl.SIGNED_DISTANCE_TYPE_WINDING_NUMBER),
                            ("pseudonormal", igl.SIGNED_DISTANCE_TYPE_PSEUDONORMAL)]:
            methods.append((f"libigl {label}", lambda v, f, p, kind=kind: igl.signed_distance(
                np.ascontiguousarray(p), np.ascontiguousarray(v), np.ascontiguousarray(f, dtype=np.int64),
                kind)[0] < 0))
    except ImportError:
        pass
    try:
        import trimesh

        # trimesh's signed distance is positive inside.
        methods.append(("trimesh proximity.signed_distance",
                        lambda v, f, p: trimesh.proximity.signed_distance(trimesh.Trimesh(v, f, process=False), p) > 0))
    except ImportError:
        pass
    cases = sign_cases()
    print("\nwrong signs (points on the wrong side / points tested)")
    print(f"{'method':36s}" + "".join(f" {name:>32s}" for name, *_ in cases))
    for label, inside in methods:
        cells = []
        for _, v, f, p, truth in cases:
            try:
                wrong = int(np.sum(np.asarray(inside(v, f, p), dtype=bool) != truth))
                cells.append(f"{wrong} / {len(p)}")
            except Exception as e:  # a peer that refuses the input counts as failing it
                cells.append(f"error: {type(e).__name__}")
        print(f"{label:36s}" + "".join(f" {c:>32s}" for c in cells))


if __name__ == "__main__":
    main()
