"""Benchmark of out-of-core decimation: hmira.dask.marching_cubes(..., decimate=ratio).

compare: an n^3 float32 gyroid (period 128 samples): in-memory hmira.marching_cubes then
         Mesh.decimate(target_ratio) against the Dask pipeline (threaded scheduler, lazily
         generated 128^3 chunks), wall seconds of each; both measured against the full-resolution
         surface with hmira.dask.decimation_quality (Hausdorff, mean, min-angle histogram).
scale:   the Dask pipeline on a LocalCluster of 2 worker processes with a memory limit each,
         streamed to a PLY: wall time, peak RSS per worker (VmHWM), worker restarts.
"""
import argparse
import json
import os
import tempfile
import time

import numpy as np

import dask
import hmira
import hmira.dask

from bench import gyroid_block, lazy_gyroid, read_ply, vm_hwm_mib


def compare(n, period, ratio, block, threads):
    vol = gyroid_block(period, {None: {"array-location": [(0, n)] * 3}})
    t0 = time.perf_counter()
    fv, ff = hmira.marching_cubes(vol, 0.0, threads=threads)
    t_mc = time.perf_counter() - t0
    m = hmira.Mesh(fv, ff)
    t1 = time.perf_counter()
    m.decimate(target_ratio=ratio)
    t_dec = time.perf_counter() - t1
    mem = (np.asarray(m.vertices), np.asarray(m.faces))
    field = lazy_gyroid(n, 128, period)
    with dask.config.set(scheduler="threads", num_workers=threads):
        t0 = time.perf_counter()
        dv, df = hmira.dask.marching_cubes(field, 0.0, decimate=ratio, block=block)
        t_dask = time.perf_counter() - t0
    same = hmira.Mesh(fv, ff)
    same.decimate(target_faces=len(df))  # in memory at the face count the Dask pipeline reached
    q_mem = hmira.dask.decimation_quality((fv, ff), mem)
    q_dask = hmira.dask.decimation_quality((fv, ff), (dv, df))
    q_same = hmira.dask.decimation_quality((fv, ff), (np.asarray(same.vertices), np.asarray(same.faces)))
    for q in (q_mem, q_dask, q_same):
        q.pop("report")
    return {"n": n, "period": period, "ratio": ratio, "block": block, "threads": threads, "full_faces": len(ff),
            "in_memory_mc_s": round(t_mc, 2), "in_memory_decimate_s": round(t_dec, 2),
            "in_memory_total_s": round(t_mc + t_dec, 2), "dask_s": round(t_dask, 2),
            "time_ratio": round(t_dask / (t_mc + t_dec), 3),
            "hausdorff_ratio_same_faces": round(q_dask["hausdorff"] / q_same["hausdorff"], 3),
            "mean_ratio_same_faces": round(q_dask["mean"] / q_same["mean"], 3),
            "in_memory": q_mem, "in_memory_same_faces": q_same, "dask": q_dask}


def scale(n, period, ratio, block, memory_limit):
    import distributed

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, memory_limit=memory_limit,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        before = set(client.scheduler_info()["workers"])
        out = os.path.join(tempfile.mkdtemp(prefix="hmira-dask-decimate-"), "gyroid.ply")
        t0 = time.perf_counter()
        hmira.dask.marching_cubes(lazy_gyroid(n, 128, period), 0.0, decimate=ratio, block=block, out=out)
        wall = time.perf_counter() - t0
        hwm = client.run(vm_hwm_mib)
        after = set(client.scheduler_info()["workers"])
    v, f = read_ply(out)
    m = hmira.Mesh(np.asarray(v), np.asarray(f["v"]))
    t = hmira.mesh_topology(m)
    return {"n": n, "period": period, "ratio": ratio, "block": block, "memory_limit": memory_limit,
            "wall_s": round(wall, 1), "vertices": len(v), "faces": len(f),
            "worker_vm_hwm_mib": {w.rsplit(":", 1)[-1]: round(r, 1) for w, r in hwm.items()},
            "workers_restarted": before != after, "client_vm_hwm_mib": round(vm_hwm_mib(), 1),
            "non_manifold_edges": t.non_manifold_edges, "boundary_loops": t.boundary_loops,
            "valid": m.validate() == []}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mode", choices=["compare", "scale"])
    p.add_argument("--n", type=int, default=256)
    p.add_argument("--period", type=float, default=128.0)
    p.add_argument("--ratio", type=float, default=0.02)
    p.add_argument("--block", type=int, default=128)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--memory-limit", default="2GiB")
    a = p.parse_args()
    if a.mode == "compare":
        r = compare(a.n, a.period, a.ratio, a.block, a.threads)
    else:
        r = scale(a.n, a.period, a.ratio, a.block, a.memory_limit)
    print(json.dumps(r, indent=1))


if __name__ == "__main__":
    main()
