"""Mesh booleans side by side: Manifold (manifold3d), libigl's copyleft.cgal.mesh_boolean and, through
boolean_bench (C++), CGAL's corefinement with Epick and hmira's mesh_boolean, on the same inputs, in
one run (hmira's row adds its operation alone on Surface_mesh and OpenMesh inputs, -1 where not built).

Inputs (written as OFF into --out, so that every tool reads the same numbers):
  sphere448:  Manifold's own perf test, Sphere(1, 448) (100,352 triangles) minus a copy translated by
              (0.5, 0.5, 0.5);
  sphere1416: the same at 1,002,528 triangles (skipped with --quick);
  gyroid:     two gyroid solids (Manifold's level set on a 128-step grid over the box, clipped by it),
              the second shifted by a fifth of the period; the difference.

Each tool is timed two ways, the median of --reps runs: the operation alone, and from arrays in to
arrays out (Manifold's construction from Mesh64 and its to_mesh64 included). A tool that raises or
returns an empty or invalid result for non-empty input is reported as refused. The output is checked
for closedness (every edge used twice, by the arrays) and its volume is printed.
Usage: peers.py --out DIR [--reps N] [--quick] [--cgal PATH/boolean_bench] [--cases a,b] [--threads N]"""
import argparse
import statistics
import subprocess
import time
from pathlib import Path

import numpy as np


def write_off(path, v, f):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(v)} {len(f)} 0\n")
        np.savetxt(out, v, fmt="%.17g")
        np.savetxt(out, np.hstack([np.full((len(f), 1), 3), f]), fmt="%d")


def closed(f):
    """Every undirected edge is used by exactly two triangles, in opposite directions."""
    if len(f) == 0:
        return True
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    directed = np.unique(e, axis=0)
    if len(directed) != len(e):
        return False
    flipped = np.unique(e[:, ::-1], axis=0)
    return bool(np.array_equal(directed, flipped))


def volume(v, f):
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6)


def inputs(quick):
    import manifold3d as mf
    out = {}
    for n in ([448] if quick else [448, 1416]):
        s = mf.Manifold.sphere(1.0, n)
        t = s.translate((0.5, 0.5, 0.5))
        out[f"sphere{n}"] = (s.to_mesh64(), t.to_mesh64())
    period = 2 * np.pi
    lo, hi = -period, period

    def gyroid(shift):
        def f(x, y, z):
            x, y, z = x + shift, y + shift, z + shift
            g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
            box = min(x - shift - lo, hi - x + shift, y - shift - lo, hi - y + shift, z - shift - lo, hi - z + shift)
            return min(-g, box)
        return f

    edge = (hi - lo) / 128
    ga = mf.Manifold.level_set(gyroid(0.0), [lo, lo, lo, hi, hi, hi], edge)
    gb = mf.Manifold.level_set(gyroid(period / 5), [lo, lo, lo, hi, hi, hi], edge)
    out["gyroid"] = (ga.to_mesh64(), gb.to_mesh64())
    return out


def arrays(mesh):
    return np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3].copy(), np.asarray(mesh.tri_verts, dtype=np.int64)


def run_manifold(va, fa, vb, fb, op, reps):
    import manifold3d as mf
    f = {"union": lambda a, b: a + b, "intersection": lambda a, b: a ^ b, "difference": lambda a, b: a - b}[op]

    def build(v, t):
        return mf.Manifold(mf.Mesh64(vert_properties=v, tri_verts=t.astype(np.uint32)))

    alone, whole = [], []
    for _ in range(reps):
        a, b = build(va, fa), build(vb, fb)
        if a.status() != mf.Error.NoError or b.status() != mf.Error.NoError:
            return None
        t0 = time.perf_counter()
        r = f(a, b)
        r.num_tri()  # Manifold evaluates lazily: force the operation
        alone.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        r2 = f(build(va, fa), build(vb, fb))
        out = r2.to_mesh64()
        v, t = arrays(out)
        whole.append(time.perf_counter() - t0)
    return statistics.median(alone), statistics.median(whole), v, t


def run_libigl(va, fa, vb, fb, op, reps):
    import igl.copyleft.cgal as ic
    name = {"union": "union", "intersection": "intersection", "difference": "minus"}[op]
    times = []
    for _ in range(reps):
        t0 = time.perf_counter()
        res = ic.mesh_boolean(va, fa, vb, fb, name)
        times.append(time.perf_counter() - t0)
    v, t = np.asarray(res[0], dtype=np.float64), np.asarray(res[1], dtype=np.int64)
    return statistics.median(times), statistics.median(times), v, t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--cgal", default="")
    ap.add_argument("--cases", default="")
    ap.add_argument("--op", default="difference")
    ap.add_argument("--threads", type=int, default=0, help="hmira's thread count (0: all cores)")
    a = ap.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    cases = inputs(a.quick)
    wanted = [c for c in a.cases.split(",") if c] or list(cases)
    print(f"{'case':12} {'tool':8} {'alone s':>9} {'arrays s':>9} {'faces':>9} {'closed':>6} {'volume':>14}")
    for name in wanted:
        ma, mb = cases[name]
        va, fa = arrays(ma)
        vb, fb = arrays(mb)
        pa, pb = out / f"{name}_a.off", out / f"{name}_b.off"
        write_off(pa, va, fa)
        write_off(pb, vb, fb)
        print(f"# {name}: {len(fa)} + {len(fb)} triangles; vol(A) {volume(va, fa):.9g}, vol(B) {volume(vb, fb):.9g}")
        rows = {}
        for tool, run in (("manifold", run_manifold), ("libigl", run_libigl)):
            if tool == "libigl" and len(fa) > 200_000:
                print(f"{name:12} {tool:8} skipped (over 200k triangles: minutes per run)")
                continue
            try:
                r = run(va, fa, vb, fb, a.op, a.reps)
            except Exception as e:  # a refusal is a result
                print(f"{name:12} {tool:8} refused: {str(e).splitlines()[0][:80]}")
                continue
            if r is None:
                print(f"{name:12} {tool:8} refused the input")
                continue
            t_alone, t_whole, v, t = r
            rows[tool] = t_whole
            print(f"{name:12} {tool:8} {t_alone:9.4f} {t_whole:9.4f} {len(t):9d} {str(closed(t)):>6} {volume(v, t):14.9g}")
        if a.cgal:
            # boolean_bench prints one line per tool (cgal, then hmira): "<tool> key=value ...".
            lines = subprocess.run([a.cgal, "--op", a.op, "--reps", str(a.reps), "--threads", str(a.threads),
                                    str(pa), str(pb)],
                                   capture_output=True, text=True).stdout.strip().splitlines()
            for line in lines:
                tool, *pairs = line.split()
                fields = dict(kv.split("=") for kv in pairs)
                note = (f"  valid={fields['valid']} self_intersecting={fields['self_intersecting']}"
                        f" refused={fields['refused']}")
                if tool == "hmira":
                    note += (f" surface_mesh={float(fields['surface_mesh']):.4f}"
                             f" openmesh={float(fields['openmesh']):.4f} cut={fields['cut']} snapped={fields['snapped']} rounding={fields['rounding']}")
                print(f"{name:12} {tool:8} {float(fields['alone']):9.4f} {float(fields['arrays']):9.4f} "
                      f"{int(fields['faces']):9d} {str(fields['closed'] == '1'):>6} {float(fields['volume']):14.9g}"
                      + note)

if __name__ == "__main__":
    main()
