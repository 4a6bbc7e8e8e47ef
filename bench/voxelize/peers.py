#!/usr/bin/env python3
"""Times the peers' voxelization of the meshes bench_voxelize --export wrote, on the same grid
(origin, spacing, dimensions) where the peer lets us choose it, and prints one table with
hmira's Google Benchmark results (JSON) and the filled-voxel counts side by side.

usage: peers.py MESH_DIR HMIRA_BENCH_BINARY THREADS...
Only the voxelization is timed (meshes are already in memory in the peer's own types)."""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


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


def load(mesh_dir):
    rows = []
    with open(f"{mesh_dir}/manifest.txt") as f:
        for line in f:
            name, res, nv, nf, dx, dy, dz, ox, oy, oz, h, solid, surface = line.split()
            rows.append(dict(name=name, res=int(res), dims=(int(dx), int(dy), int(dz)),
                             origin=(float(ox), float(oy), float(oz)), h=float(h),
                             hmira_solid=int(solid), hmira_surface=int(surface)))
    meshes = {}
    for r in rows:
        if r["name"] not in meshes:
            v = np.fromfile(f"{mesh_dir}/{r['name']}.vertices", dtype="<f8").reshape(-1, 3)
            fcs = np.fromfile(f"{mesh_dir}/{r['name']}.faces", dtype="<i4").reshape(-1, 3)
            meshes[r["name"]] = (v, fcs)
    return rows, meshes


def vtk_stencil(v, f, r, threads):
    import vtk
    from vtk.util import numpy_support
    vtk.vtkSMPTools.SetBackend("STDThread")
    vtk.vtkSMPTools.Initialize(threads)
    pts = vtk.vtkPoints()
    pts.SetData(numpy_support.numpy_to_vtk(v, deep=True))
    cells = vtk.vtkCellArray()
    offsets = numpy_support.numpy_to_vtk(np.arange(0, 3 * len(f) + 1, 3, dtype=np.int64), deep=True)
    conn = numpy_support.numpy_to_vtk(f.astype(np.int64).ravel(), deep=True)
    cells.SetData(offsets, conn)
    pd = vtk.vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(cells)
    st = vtk.vtkPolyDataToImageStencil()
    st.SetInputData(pd)
    st.SetOutputOrigin(*r["origin"])
    st.SetOutputSpacing(r["h"], r["h"], r["h"])
    st.SetOutputWholeExtent(0, r["dims"][0] - 1, 0, r["dims"][1] - 1, 0, r["dims"][2] - 1)

    def run():
        st.Modified()
        st.Update()
        return st.GetOutput()
    ms, stencil = best_of(run, 2)
    to_img = vtk.vtkImageStencilToImage()
    to_img.SetInputData(stencil)
    to_img.SetInsideValue(1)
    to_img.SetOutsideValue(0)
    to_img.SetOutputScalarTypeToUnsignedChar()
    to_img.Update()
    count = int(numpy_support.vtk_to_numpy(to_img.GetOutput().GetPointData().GetScalars()).sum())
    return ms, count


def trimesh_fill(v, f, r):
    import trimesh
    m = trimesh.Trimesh(vertices=v, faces=f, process=False)
    ms, vg = best_of(lambda: m.voxelized(pitch=r["h"]).fill(), 1)
    return ms, int(vg.filled_count)


def open3d_surface(v, f, r):
    import open3d as o3d
    m = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(v), o3d.utility.Vector3iVector(f.astype(np.int32)))
    lo = np.array(r["origin"]) - 0.5 * r["h"]
    hi = lo + np.array(r["dims"]) * r["h"]
    ms, vg = best_of(lambda: o3d.geometry.VoxelGrid.create_from_triangle_mesh_within_bounds(m, r["h"], lo, hi), 2)
    return ms, len(vg.get_voxels())


def main():
    mesh_dir, bench, threads = sys.argv[1], sys.argv[2], [int(t) for t in sys.argv[3:]]
    rows, meshes = load(mesh_dir)
    skip_trimesh = os.environ.get("HMIRA_BENCH_SKIP_TRIMESH_ABOVE", "30000000")
    out = []
    for r in rows:
        v, f = meshes[r["name"]]
        for t in threads:
            h = hmira_ms(bench, f"hmira_voxelize/{r['name']}/{r['res']}", t)
            peers = [("vtkPolyDataToImageStencil", "solid", r["hmira_solid"], vtk_stencil(v, f, r, t))]
            if t == 1:  # single-threaded peers
                if len(f) * r["res"] <= int(skip_trimesh):
                    peers.append(("trimesh voxelized.fill", "solid", r["hmira_solid"], trimesh_fill(v, f, r)))
                peers.append(("Open3D VoxelGrid", "surface", r["hmira_surface"], open3d_surface(v, f, r)))
            for peer, kind, hcount, (ms, count) in peers:
                out.append((r["name"], r["res"], t, h, peer, ms, h / ms, kind, hcount, count))
            print(f"# done {r['name']} {r['res']} threads={t}", file=sys.stderr, flush=True)
    hdr = ("mesh", "res", "thr", "hmira ms", "peer", "peer ms", "hmira/peer", "counted", "hmira voxels", "peer voxels")
    print("| " + " | ".join(hdr) + " |")
    print("|" + "---|" * len(hdr))
    for row in out:
        name, res, t, h, peer, ms, ratio, kind, hc, pc = row
        print(f"| {name} | {res} | {t} | {h:.1f} | {peer} | {ms:.1f} | {ratio:.2f} | {kind} | {hc} | {pc} |")


if __name__ == "__main__":
    main()
