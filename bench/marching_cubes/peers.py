#!/usr/bin/env python3
"""Times the peers' marching cubes on the volumes bench_marching_cubes --export wrote, and
prints one table with hmira's Google Benchmark results (JSON) side by side.

usage: peers.py VOLUME_DIR HMIRA_BENCH_BINARY THREADS...
Only the extraction is timed (the volume is already in memory, in the peer's own layout)."""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def load(volume_dir):
    vols = []
    with open(f"{volume_dir}/manifest.txt") as f:
        for line in f:
            name, nx, ny, nz, iso, inside, tris, welded, closed = line.split()
            data = np.fromfile(f"{volume_dir}/{name}.raw", dtype="<f4").reshape(int(nz), int(ny), int(nx))
            vols.append(dict(name=name, dims=(int(nx), int(ny), int(nz)), iso=float(iso), inside=inside,
                             data=data, hmira_tris=int(tris), hmira_welded=welded, hmira_closed=closed))
    return vols


def hmira_ms(bench, name, threads):
    """Runs hmira's Google Benchmark for one case right before its peers, so that both sides
    see the same machine load; returns the real time in ms."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([bench, f"--benchmark_filter=^{name}/{threads}/", f"--benchmark_out={out.name}",
                        "--benchmark_out_format=json"], check=True, stdout=subprocess.DEVNULL)
        runs = [b for b in json.load(open(out.name))["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    return runs[0]["real_time"] if runs else float("nan")


def best_of(fn, repeat):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best * 1000.0, out


def mesh_state(verts, faces):
    """(welded, closed): no two vertices share a position; every edge has exactly two faces."""
    verts = np.asarray(verts, dtype=np.float64)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    welded = len(np.unique(verts, axis=0)) == len(verts)
    e = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    e.sort(axis=1)
    _, counts = np.unique(e[:, 0] * (len(verts) + 1) + e[:, 1], return_counts=True)
    closed = bool(np.all(counts == 2))
    return ("welded" if welded else "unwelded"), ("closed" if closed else "open")


def vtk_image(vol):
    import vtk
    from vtk.util import numpy_support
    img = vtk.vtkImageData()
    img.SetDimensions(*vol["dims"])
    arr = numpy_support.numpy_to_vtk(vol["data"].ravel(order="C"), deep=False, array_type=vtk.VTK_FLOAT)
    img.GetPointData().SetScalars(arr)
    return img


def vtk_filter(cls, vol, threads):
    """A VTK contour filter of class `cls` on `vol` at its iso value, on `threads` STDThread
    threads, computing the surface only (no normals, scalars or gradients), as hmira does."""
    import vtk
    vtk.vtkSMPTools.SetBackend("STDThread")
    vtk.vtkSMPTools.Initialize(threads)
    f = cls()
    f.SetInputData(vtk_image(vol))
    f.SetValue(0, vol["iso"])
    f.ComputeNormalsOff()
    f.ComputeScalarsOff()
    if hasattr(f, "ComputeGradientsOff"):
        f.ComputeGradientsOff()
    return f


def vtk_run(cls, vol, threads):
    from vtk.util import numpy_support
    f = vtk_filter(cls, vol, threads)

    def run():
        f.Modified()
        f.Update()
        return f.GetOutput()
    ms, out = best_of(run, 3)
    pts = numpy_support.vtk_to_numpy(out.GetPoints().GetData()) if out.GetNumberOfPoints() else np.zeros((0, 3))
    polys = numpy_support.vtk_to_numpy(out.GetPolys().GetConnectivityArray()) if out.GetNumberOfPolys() else np.zeros(0)
    return ms, out.GetNumberOfPolys(), mesh_state(pts, polys)


def skimage_run(vol):
    from skimage import measure
    data = np.ascontiguousarray(vol["data"].transpose(2, 1, 0))  # (x, y, z) indexing like the others
    ms, (v, f, _, _) = best_of(lambda: measure.marching_cubes(data, vol["iso"]), 2)
    return ms, len(f), mesh_state(v, f)


def mcubes_run(vol):
    import mcubes
    data = np.ascontiguousarray(vol["data"].transpose(2, 1, 0).astype(np.float64))
    ms, (v, f) = best_of(lambda: mcubes.marching_cubes(data, vol["iso"]), 2)
    return ms, len(f), mesh_state(v, f)


def main():
    volume_dir, bench, threads = sys.argv[1], sys.argv[2], [int(t) for t in sys.argv[3:]]
    hm = {}
    import vtk
    rows = []
    for vol in load(volume_dir):
        for t in threads:
            h = hm[(vol["name"], t)] = hmira_ms(bench, f"hmira_mc/{vol['name']}", t)
            peers = [("vtkFlyingEdges3D", vtk_run(vtk.vtkFlyingEdges3D, vol, t)),
                     ("vtkMarchingCubes", vtk_run(vtk.vtkMarchingCubes, vol, t))]
            if t == 1:  # single-threaded libraries
                peers += [("skimage", skimage_run(vol)), ("PyMCubes", mcubes_run(vol))]
            for peer, (ms, ntris, (welded, closed)) in peers:
                rows.append((vol["name"], t, h, peer, ms, h / ms, vol["hmira_tris"], ntris, welded, closed,
                             f"{vol['hmira_welded']}/{vol['hmira_closed']}"))
            print(f"# done {vol['name']} threads={t}", file=sys.stderr, flush=True)
    hdr = ("volume", "thr", "hmira ms", "peer", "peer ms", "hmira/peer", "hmira tris", "peer tris", "peer output", "hmira output")
    print("| " + " | ".join(hdr) + " |")
    print("|" + "---|" * len(hdr))
    for (name, t, h, peer, ms, ratio, ht, pt, welded, closed, hstate) in rows:
        print(f"| {name} | {t} | {h:.1f} | {peer} | {ms:.1f} | {ratio:.2f} | {ht} | {pt} | {welded}/{closed} | {hstate} |")
    # hmira's own scaling
    for vol in load(volume_dir):
        one = hm.get((vol["name"], 1))
        two = hm.get((vol["name"], 2))
        if one and two:
            print(f"hmira {vol['name']}: 2 threads / 1 thread = {two / one:.2f}")


if __name__ == "__main__":
    main()
