"""Decimation side by side from Python: hmira's Mesh.decimate against pyfqmr, fast-simplification,
Open3D's simplify_quadric_decimation and pymeshlab's quadric edge collapse, on the same arrays.
Each case is timed as the call alone (set-up outside), median of --reps runs with the libraries
alternated run by run; then the symmetric Hausdorff and mean distance (200k area-uniform samples on
each surface, the distance to the other surface exact over the triangles of the 16 nearest dense
samples), the minimum-angle 1st percentile, triangles under 1 degree and non-manifold edges.
Usage: peers.py DATA_DIR [--reps N] [--cases armadillo2,bunny00,fandisk,elephant] [--ratios 0.01,0.1]
       [--out DIR] (writes every output mesh as OFF there)"""
import argparse
import statistics
import time
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree


def read_off(path):
    tokens = [line.split("#")[0] for line in Path(path).read_text().splitlines()]
    words = " ".join(tokens).split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    v = np.array(words[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        faces.append([int(x) for x in words[at + 1:at + 1 + k]])
        at += 1 + k
    tris = [[f[0], f[i], f[i + 1]] for f in faces for i in range(1, len(f) - 1)]
    return v, np.array(tris, dtype=np.int64)


def write_off(path, v, f):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(v)} {len(f)} 0\n")
        np.savetxt(out, v, fmt="%.17g")
        np.savetxt(out, np.hstack([np.full((len(f), 1), 3), f]), fmt="%d")


def sample(v, f, n, rng):
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    tri = rng.choice(len(f), size=n, p=area / area.sum())
    r1, r2 = rng.random(n), rng.random(n)
    s = np.sqrt(r1)
    w0, w1, w2 = 1 - s, s * (1 - r2), s * r2
    return w0[:, None] * a[tri] + w1[:, None] * b[tri] + w2[:, None] * c[tri], tri


def point_triangle_distance(p, a, b, c):
    """Exact distance from points p to triangles (a, b, c), row by row (Ericson's regions)."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = np.einsum("ij,ij->i", ab, ap), np.einsum("ij,ij->i", ac, ap)
    bp = p - b
    d3, d4 = np.einsum("ij,ij->i", ab, bp), np.einsum("ij,ij->i", ac, bp)
    cp = p - c
    d5, d6 = np.einsum("ij,ij->i", ab, cp), np.einsum("ij,ij->i", ac, cp)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    denom = va + vb + vc
    with np.errstate(divide="ignore", invalid="ignore"):
        v = np.where(denom != 0, vb / denom, 0.0)
        w = np.where(denom != 0, vc / denom, 0.0)
        q = a + ab * v[:, None] + ac * w[:, None]
        # Edge and vertex regions.
        t_ab = np.clip(d1 / np.where(d1 - d3 != 0, d1 - d3, 1), 0, 1)
        t_ac = np.clip(d2 / np.where(d2 - d6 != 0, d2 - d6, 1), 0, 1)
        e = (d4 - d3) + (d5 - d6)
        t_bc = np.clip((d4 - d3) / np.where(e != 0, e, 1), 0, 1)
    cands = [q, a + ab * t_ab[:, None], a + ac * t_ac[:, None], b + (c - b) * t_bc[:, None]]
    inside = (va >= 0) & (vb >= 0) & (vc >= 0) & (denom > 0)
    dist = np.linalg.norm(p - cands[0], axis=1)
    dist = np.where(inside, dist, np.inf)
    for q in cands[1:]:
        dist = np.minimum(dist, np.linalg.norm(p - q, axis=1))
    return dist


def one_sided(points, v, f, dense, dense_tri, tree, k=16):
    _, idx = tree.query(points, k=k)
    best = np.full(len(points), np.inf)
    for j in range(k):
        t = f[dense_tri[idx[:, j]]]
        best = np.minimum(best, point_triangle_distance(points, v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]))
    return best


def quality(va, fa, vb, fb, samples=200_000, seed=1):
    rng = np.random.default_rng(seed)
    pa, _ = sample(va, fa, samples, rng)
    pb, _ = sample(vb, fb, samples, rng)
    da, ta = sample(va, fa, 4 * samples, rng)
    db, tb = sample(vb, fb, 4 * samples, rng)
    ab = one_sided(pa, vb, fb, db, tb, cKDTree(db))
    ba = one_sided(pb, va, fa, da, ta, cKDTree(da))
    diag = np.linalg.norm(va.max(0) - va.min(0))
    return max(ab.max(), ba.max()), 0.5 * (ab.mean() + ba.mean()), diag


def min_angles(v, f):
    p = v[f]
    out = []
    for i in range(3):
        u, w = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        cos = np.einsum("ij,ij->i", u, w) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(w, axis=1), 1e-300)
        out.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return np.min(out, axis=0)


def non_manifold_edges(f):
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    _, counts = np.unique(e, axis=0, return_counts=True)
    return int((counts > 2).sum())


def peers():
    """name -> (prepare(V, F, target) -> state, run(state) -> state, result(state) -> (V, F))."""
    out = {}
    import hmira

    out["hmira"] = (lambda v, f, t: [hmira.Mesh(v, f), t],
                    lambda s: s[0].decimate(target_faces=s[1]),
                    lambda s: (np.asarray(s[0].vertices), np.asarray(s[0].faces, dtype=np.int64)))
    try:
        import pyfqmr

        def prep(v, f, t):
            s = pyfqmr.Simplify()
            s.setMesh(v, f)
            return [s, t]
        out["pyfqmr"] = (prep, lambda s: s[0].simplify_mesh(target_count=s[1], verbose=False),
                         lambda s: s[0].getMesh()[:2])
    except ImportError:
        pass
    try:
        import fast_simplification
        out["fast_simplification"] = (
            lambda v, f, t: {"v": v, "f": f, "t": t},
            lambda s: s.__setitem__("r", fast_simplification.simplify(s["v"], s["f"], 1 - s["t"] / len(s["f"]))),
            lambda s: s["r"])
    except ImportError:
        pass
    try:
        import open3d as o3d

        def prep(v, f, t):
            return {"m": o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(v), o3d.utility.Vector3iVector(f)),
                    "t": t}
        out["open3d"] = (prep, lambda s: s.__setitem__("r", s["m"].simplify_quadric_decimation(
            target_number_of_triangles=s["t"])),
            lambda s: (np.asarray(s["r"].vertices), np.asarray(s["r"].triangles)))
    except ImportError:
        pass
    try:
        import pymeshlab

        def prep(v, f, t):
            ms = pymeshlab.MeshSet()
            ms.add_mesh(pymeshlab.Mesh(v, f))
            return {"ms": ms, "t": t}
        out["pymeshlab"] = (prep, lambda s: s["ms"].meshing_decimation_quadric_edge_collapse(targetfacenum=s["t"]),
                            lambda s: (s["ms"].current_mesh().vertex_matrix(), s["ms"].current_mesh().face_matrix()))
    except ImportError:
        pass
    return out


def load_case(data, name):
    import hmira
    if name == "armadillo2":
        v, f = read_off(Path(data) / "meshes" / "armadillo.off")
        m = hmira.Mesh(v, f)
        m.subdivide(scheme="loop", levels=2)
        return np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)
    return read_off(Path(data) / "meshes" / f"{name}.off")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("data")
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--cases", default="armadillo2,bunny00,fandisk,elephant")
    ap.add_argument("--ratios", default="0.01,0.1")
    ap.add_argument("--peers", default="")
    ap.add_argument("--out", default="")
    args = ap.parse_args()
    libs = peers()
    if args.peers:
        libs = {k: v for k, v in libs.items() if k in args.peers.split(",")}
    fq = [n for n in ("pyfqmr", "fast_simplification") if n in libs]
    print(f"{'case':18s} {'library':20s} {'time s':>8s} {'faces':>7s} {'Hausdorff':>10s} {'% diag':>7s} "
          f"{'mean':>10s} {'minang p1':>9s} {'<1deg':>6s} {'nm edges':>8s}")
    summary = []
    for case in args.cases.split(","):
        v, f = load_case(args.data, case)
        v = np.ascontiguousarray(v, dtype=np.float64)
        for ratio in (float(r) for r in args.ratios.split(",")):
            target = int(round(ratio * len(f)))
            times = {n: [] for n in libs}
            results = {}
            for _ in range(args.reps):
                for name, (prep, run, res) in libs.items():
                    s = prep(v, np.ascontiguousarray(f, dtype=np.int32 if name != "hmira" else np.int64), target)
                    t0 = time.perf_counter()
                    run(s)
                    times[name].append(time.perf_counter() - t0)
                    results[name] = s
            label = f"{case} {ratio:g}"
            rows = {}
            for name, (prep, run, res) in libs.items():
                vb, fb = res(results[name])
                vb, fb = np.asarray(vb, dtype=np.float64), np.asarray(fb, dtype=np.int64)
                if args.out:
                    Path(args.out).mkdir(parents=True, exist_ok=True)
                    write_off(Path(args.out) / f"{case}_{ratio:g}_{name}.off", vb, fb)
                h, mean, diag = quality(v, f, vb, fb)
                ang = min_angles(vb, fb)
                t = statistics.median(times[name])
                rows[name] = (t, h)
                print(f"{label:18s} {name:20s} {t:8.3f} {len(fb):7d} {h:10.4g} {100 * h / diag:7.2f} {mean:10.4g} "
                      f"{np.percentile(ang, 1):9.2f} {int((ang < 1).sum()):6d} {non_manifold_edges(fb):8d}", flush=True)
            if "hmira" in rows and fq:
                fastest = min(fq, key=lambda n: rows[n][0])
                best_h = min(rows[n][1] for n in rows if n != "hmira")
                summary.append((label, rows["hmira"][0] / rows[fastest][0], fastest, rows["hmira"][1] / best_h))
    if summary:
        print("\nratios: time hmira / faster Fast-Quadric peer; Hausdorff hmira / best peer")
        for label, tr, who, hr in summary:
            print(f"  {label:18s} time {tr:6.2f} (vs {who:19s})  Hausdorff {hr:6.2f}")


if __name__ == "__main__":
    main()
