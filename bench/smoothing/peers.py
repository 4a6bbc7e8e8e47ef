"""Smoothing and mesh construction from Python, hmira beside its Python peers, in one run:
- Laplacian (uniform weights, lambda 0.5, 10 steps) beside trimesh.smoothing.filter_laplacian
  (the same umbrella operator as a scipy sparse matrix, no volume constraint);
- Taubin (10 lambda/mu pairs, lambda 0.5, mu -0.53) beside trimesh.smoothing.filter_taubin,
  whose `iterations` counts single steps: 20;
- hmira at 1 and at 2 threads;
- hmira.Mesh(V, F) beside Open3D's TriangleMesh, pyfqmr's setMesh and trimesh.Trimesh
  (process=False) on the same arrays.
Inputs: bunny00.off and armadillo.off Loop-subdivided twice (~832k triangles), from the
libcgal-demo data (HMIRA_TEST_DATA or --data). Every peer works on a fresh mesh made outside the
timed region, so each call builds its operator as hmira builds its rows. Each line is the median
of `repeats` wall times, hmira and the peer alternated run by run; ratios are hmira / peer.
    python bench/smoothing/peers.py [--data DIR] [--repeats 5]
"""
import argparse
import os
import statistics
import time

import numpy as np

import hmira


def optional(module):
    try:
        return __import__(module, fromlist=["_"])
    except ImportError:
        return None


trimesh = optional("trimesh")
o3d = optional("open3d")
pyfqmr = optional("pyfqmr")


def timed(prepare, run):
    state = prepare()
    start = time.perf_counter()
    out = run(state)
    elapsed = time.perf_counter() - start
    return elapsed, out


def alternate(cases, repeats):
    """cases: name -> (prepare, run). Runs them in turn `repeats` times; median wall time each."""
    times = {name: [] for name in cases}
    outs = {}
    for _ in range(repeats):
        for name, (prepare, run) in cases.items():
            t, outs[name] = timed(prepare, run)
            times[name].append(t)
    return {name: statistics.median(ts) for name, ts in times.items()}, outs


def report(title, medians, ours, peers):
    print(f"\n{title}")
    for name, t in medians.items():
        print(f"  {name:<44} {t * 1e3:9.1f} ms")
    for peer in peers:
        if peer in medians:
            print(f"  ratio {ours} / {peer}: {medians[ours] / medians[peer]:.3f}")


def inputs(data):
    bunny = hmira.read_mesh(os.path.join(data, "meshes", "bunny00.off"))
    arm = hmira.read_mesh(os.path.join(data, "meshes", "armadillo.off"))
    arm.subdivide(scheme="loop", levels=2)
    out = {}
    for name, m in (("bunny00", bunny), ("armadillo Loop x2", arm)):
        out[name] = (np.array(m.vertices, dtype=np.float64), np.ascontiguousarray(m.faces, dtype=np.int64))
    return out


def smoothing_cases(V, F, taubin):
    def fresh_hmira():
        return hmira.Mesh(V, F)

    def ours(threads):
        if taubin:
            return lambda m: (m.taubin_smooth(iterations=10, lambda_=0.5, mu=-0.53, threads=threads), m)[1]
        return lambda m: (m.laplacian_smooth(iterations=10, lambda_=0.5, threads=threads), m)[1]

    cases = {"hmira, 1 thread": (fresh_hmira, ours(1)), "hmira, 2 threads": (fresh_hmira, ours(2))}
    if trimesh is not None:
        from trimesh import smoothing

        def fresh_trimesh():
            return trimesh.Trimesh(V.copy(), F, process=False)

        if taubin:
            run = lambda t: smoothing.filter_taubin(t, lamb=0.5, nu=0.53, iterations=20)  # noqa: E731
        else:
            run = lambda t: smoothing.filter_laplacian(  # noqa: E731
                t, lamb=0.5, iterations=10, implicit_time_integration=False, volume_constraint=False)
        cases["trimesh"] = (fresh_trimesh, run)
    return cases


def construction_cases(V, F):
    F32 = F.astype(np.int32)
    cases = {"hmira.Mesh(V, F int64)": (lambda: None, lambda _: hmira.Mesh(V, F)),
             "hmira.Mesh(V, F int32)": (lambda: None, lambda _: hmira.Mesh(V, F32))}
    if o3d is not None:
        cases["open3d TriangleMesh"] = (lambda: None, lambda _: o3d.geometry.TriangleMesh(
            o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F32)))
    if pyfqmr is not None:
        def fqmr(_):
            s = pyfqmr.Simplify()
            s.setMesh(V, F32)
            return s
        cases["pyfqmr setMesh"] = (lambda: None, fqmr)
    if trimesh is not None:
        cases["trimesh.Trimesh(process=False)"] = (lambda: None, lambda _: trimesh.Trimesh(V, F, process=False))
    return cases


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", default=os.environ.get("HMIRA_TEST_DATA", "build/test-data"))
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    if trimesh is None:
        print("trimesh: not installed (no smoothing peer)")
    for name, (V, F) in inputs(args.data).items():
        print(f"\n== {name}: {len(V)} vertices, {len(F)} triangles")
        for taubin in (False, True):
            what = "Taubin, 10 pairs (trimesh 20 steps)" if taubin else "Laplacian, 10 steps"
            medians, outs = alternate(smoothing_cases(V, F, taubin), args.repeats)
            report(what, medians, "hmira, 1 thread", ["trimesh", "hmira, 2 threads"])
            if "trimesh" in outs:
                gap = np.abs(np.asarray(outs["hmira, 1 thread"].vertices) - outs["trimesh"].vertices).max()
                print(f"  largest coordinate difference hmira - trimesh: {gap:.3g}")
        medians, _ = alternate(construction_cases(V, F), args.repeats)
        report("Mesh construction from (V, F) arrays", medians, "hmira.Mesh(V, F int64)",
               ["open3d TriangleMesh", "pyfqmr setMesh", "trimesh.Trimesh(process=False)"])


if __name__ == "__main__":
    main()
