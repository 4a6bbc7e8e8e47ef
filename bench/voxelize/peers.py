#!/usr/bin/env python3
"""Times the peers' voxelization of the meshes bench_voxelize --export wrote, on the same grid
(origin, spacing, dimensions) where the peer lets us choose it, and prints one table with
hmira's Google Benchmark results (JSON, median of 5 repetitions) and the peers' (median of 5
runs) side by side, with the filled-voxel counts. Ratios are of CPU time of the whole process
(all threads), so that a machine loaded by other work disturbs them less than wall time; the
wall times (medians too) are printed beside them, for the 2-thread rows. hmira's
conservative and centres modes are both timed against VTK's stencil; hmira's centres grid is
compared with the stencil (Tolerance 0) voxel for voxel, except voxels whose centre lies within
1e-9 of the surface.

usage: peers.py MESH_DIR HMIRA_BENCH_BINARY THREADS...
HMIRA_BENCH_MESHES=a,b limits the meshes; HMIRA_BENCH_RESOLUTIONS=256,512 the resolutions;
HMIRA_BENCH_VTK_ONLY=1 skips trimesh and Open3D; HMIRA_BENCH_BASELINE=<an older bench_voxelize>
adds its times (run right before the current binary's) for a before/after column;
HMIRA_BENCH_ROUNDS=N (default 1) measures hmira and VTK N times in turn and gives VTK rows the
median of the N per-round ratios (the times shown are medians over the rounds). Only the
voxelization is timed (meshes are already in memory in the peer's own types)."""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def hmira_ms(bench, name, threads):
    """Runs hmira's Google Benchmark for one case right before its peers, so that both sides
    see the same machine load; returns the median CPU time (all threads) and the median wall time
    of 5 repetitions in ms."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([bench, f"--benchmark_filter=^{name}/{threads}/", f"--benchmark_out={out.name}",
                        "--benchmark_out_format=json", "--benchmark_repetitions=5", "--benchmark_min_time=0.2"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        runs = [b for b in json.load(open(out.name))["benchmarks"] if b.get("aggregate_name") == "median"]
    return (runs[0]["cpu_time"], runs[0]["real_time"]) if runs else (float("nan"), float("nan"))


def medians(pairs):
    """The element-wise median of (CPU ms, wall ms) pairs."""
    return tuple(float(np.median([p[i] for p in pairs])) for i in range(2))


def best_of(fn, repeat):
    """The median CPU time (process: all threads) and the median wall time of `repeat` runs in
    ms (the name is historical), and the last output."""
    times, walls, out = [], [], None
    for _ in range(repeat):
        t0, w0 = time.process_time(), time.perf_counter()
        out = fn()
        times.append(time.process_time() - t0)
        walls.append(time.perf_counter() - w0)
    return (float(np.median(times)) * 1000.0, float(np.median(walls)) * 1000.0), out


def load(mesh_dir):
    rows = []
    with open(f"{mesh_dir}/manifest.txt") as f:
        for line in f:
            name, res, nv, nf, dx, dy, dz, ox, oy, oz, h, solid, surface, centres = line.split()
            rows.append(dict(name=name, res=int(res), dims=(int(dx), int(dy), int(dz)),
                             origin=(float(ox), float(oy), float(oz)), h=float(h),
                             hmira_solid=int(solid), hmira_surface=int(surface), hmira_centres=int(centres)))
    only = os.environ.get("HMIRA_BENCH_MESHES")
    if only:
        rows = [r for r in rows if r["name"] in only.split(",")]
    res = os.environ.get("HMIRA_BENCH_RESOLUTIONS")
    if res:
        rows = [r for r in rows if str(r["res"]) in res.split(",")]
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
    ms, stencil = best_of(run, 5)  # (CPU, wall)
    to_img = vtk.vtkImageStencilToImage()
    to_img.SetInputData(stencil)
    to_img.SetInsideValue(1)
    to_img.SetOutsideValue(0)
    to_img.SetOutputScalarTypeToUnsignedChar()
    to_img.Update()
    img = numpy_support.vtk_to_numpy(to_img.GetOutput().GetPointData().GetScalars())
    return ms, int(img.sum()), img.reshape(r["dims"][2], r["dims"][1], r["dims"][0])


def hmira_centres_grid(mesh_dir, r):
    """hmira's centres bits as a (z, y, x) bool array (rows of 64-bit words, x fastest)."""
    nx, ny, nz = r["dims"]
    words = (nx + 63) // 64
    w = np.fromfile(f"{mesh_dir}/{r['name']}_{r['res']}.centres", dtype="<u8").reshape(nz, ny, words)
    bits = np.unpackbits(w.view(np.uint8), axis=2, bitorder="little")[:, :, :nx]
    return bits.astype(bool)


def compare_with_vtk(v, f, r, ours, theirs):
    """Voxels where hmira's centres grid and VTK's stencil differ, and how many of those have
    their centre farther than 1e-9 from the surface (those would be real disagreements)."""
    diff = np.argwhere(ours != theirs.astype(bool))
    if len(diff) == 0:
        return 0, 0, 0.0, 0, 0
    import vtk
    from vtk.util import numpy_support
    pts = vtk.vtkPoints()
    pts.SetData(numpy_support.numpy_to_vtk(v, deep=True))
    cells = vtk.vtkCellArray()
    cells.SetData(numpy_support.numpy_to_vtk(np.arange(0, 3 * len(f) + 1, 3, dtype=np.int64), deep=True),
                  numpy_support.numpy_to_vtk(f.astype(np.int64).ravel(), deep=True))
    pd = vtk.vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(cells)
    loc = vtk.vtkStaticCellLocator()
    loc.SetDataSet(pd)
    loc.BuildLocator()
    centres = np.asarray(r["origin"]) + r["h"] * diff[:, ::-1].astype(float)
    closest, cell, sub, d2 = [0.0, 0.0, 0.0], vtk.reference(0), vtk.reference(0), vtk.reference(0.0)
    dist = []
    for p in centres[:200000]:
        loc.FindClosestPoint(p.tolist(), closest, cell, sub, d2)
        dist.append(float(d2) ** 0.5)
    dist = np.asarray(dist)
    # Who is right where they differ beyond 1e-9: the generalized winding number (double,
    # O(F) per point) of up to 1000 of those centres.
    far = centres[:200000][dist > 1e-9][:1000]
    hmira_right = 0
    for p, (z, y, x) in zip(far, diff[:200000][dist > 1e-9][:1000]):
        a, b, c = v[f[:, 0]] - p, v[f[:, 1]] - p, v[f[:, 2]] - p
        la, lb, lc = (np.linalg.norm(q, axis=1) for q in (a, b, c))
        num = np.einsum("ij,ij->i", a, np.cross(b, c))
        den = la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", b, c) * la + np.einsum("ij,ij->i", c, a) * lb
        inside = (2 * np.arctan2(num, den)).sum() / (4 * np.pi) > 0.5
        hmira_right += bool(inside) == bool(ours[z, y, x])
    return len(diff), int((dist > 1e-9).sum()) + max(0, len(diff) - 200000), float(dist.max()), hmira_right, len(far)


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
    # Checked before the meshes load, so a bad value stops the run at once.
    rounds_text = os.environ.get("HMIRA_BENCH_ROUNDS", "1")
    if not rounds_text.isdigit() or not 1 <= int(rounds_text) <= 100:
        sys.exit(f"peers.py: HMIRA_BENCH_ROUNDS takes a whole number from 1 to 100, not '{rounds_text}'")
    rounds = int(rounds_text)
    rows, meshes = load(mesh_dir)
    skip_trimesh = os.environ.get("HMIRA_BENCH_SKIP_TRIMESH_ABOVE", "30000000")
    baseline = os.environ.get("HMIRA_BENCH_BASELINE")
    before = {}
    out, exact = [], []
    for r in rows:
        v, f = meshes[r["name"]]
        for t in threads:
            if baseline:
                before[(r["name"], r["res"], t, "solid")] = hmira_ms(baseline, f"hmira_voxelize/{r['name']}/{r['res']}", t)
                before[(r["name"], r["res"], t, "centres")] = hmira_ms(baseline, f"hmira_voxelize_centres/{r['name']}/{r['res']}", t)
            # Rounds of (hmira conservative, hmira centres, VTK), each ratio taken within its round:
            # this machine's speed drifts by a third over minutes, more than any one row's margin.
            hs, hcs, vs = [], [], []
            for _ in range(rounds):
                hs.append(hmira_ms(bench, f"hmira_voxelize/{r['name']}/{r['res']}", t))
                hcs.append(hmira_ms(bench, f"hmira_voxelize_centres/{r['name']}/{r['res']}", t))
                vms, vcount, vimg = vtk_stencil(v, f, r, t)
                vs.append(vms)
            h, hc, vms = medians(hs), medians(hcs), medians(vs)
            solid_ratio = float(np.median([a[0] / b[0] for a, b in zip(hs, vs)]))
            centres_ratio = float(np.median([a[0] / b[0] for a, b in zip(hcs, vs)]))
            out.append((r["name"], r["res"], t, hc, "centres vs vtkPolyDataToImageStencil", vms, centres_ratio, "centres",
                        r["hmira_centres"], vcount))
            if t == threads[0]:
                exact.append((r["name"], r["res"], r["hmira_centres"], vcount) +
                             compare_with_vtk(v, f, r, hmira_centres_grid(mesh_dir, r), vimg))
            peers = [("vtkPolyDataToImageStencil", "solid", r["hmira_solid"], (vms, vcount))]
            if t == 1 and not os.environ.get("HMIRA_BENCH_VTK_ONLY"):  # single-threaded peers
                if len(f) * r["res"] <= int(skip_trimesh):
                    peers.append(("trimesh voxelized.fill", "solid", r["hmira_solid"], trimesh_fill(v, f, r)))
                peers.append(("Open3D VoxelGrid", "surface", r["hmira_surface"], open3d_surface(v, f, r)))
            for peer, kind, hcount, (ms, count) in peers:
                ratio = solid_ratio if peer == "vtkPolyDataToImageStencil" else h[0] / ms[0]
                out.append((r["name"], r["res"], t, h, peer, ms, ratio, kind, hcount, count))
            print(f"# done {r['name']} {r['res']} threads={t}", file=sys.stderr, flush=True)
    hdr = ("mesh", "res", "thr", "hmira CPU ms", "peer", "peer CPU ms", "hmira/peer (CPU)", "hmira wall ms", "peer wall ms",
           "hmira/peer (wall)", "counted", "hmira voxels", "peer voxels")
    if baseline:
        hdr += ("baseline CPU ms", "baseline/peer")
    print("| " + " | ".join(hdr) + " |")
    print("|" + "---|" * len(hdr))
    for row in out:
        name, res, t, h, peer, ms, ratio, kind, hc, pc = row
        line = (f"| {name} | {res} | {t} | {h[0]:.2f} | {peer} | {ms[0]:.2f} | {ratio:.2f} | {h[1]:.2f} | {ms[1]:.2f} | "
                f"{h[1] / ms[1]:.2f} | {kind} | {hc} | {pc} |")
        if baseline:
            b = before.get((name, res, t, "centres" if kind == "centres" else "solid"), (float("nan"),))[0]
            line += f" {b:.2f} | {b / ms[0]:.2f} |"
        print(line)
    print()
    print("| mesh | res | hmira centres voxels | VTK stencil voxels | voxels that differ | of those, centre > 1e-9 "
          "from the surface | farthest from the surface | hmira agrees with the winding number (checked) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, res, hc, vc, nd, nf, dmax, right, checked in exact:
        print(f"| {name} | {res} | {hc} | {vc} | {nd} | {nf} | {dmax:.2g} | {right} ({checked}) |")


if __name__ == "__main__":
    main()
