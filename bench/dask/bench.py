"""Scale benchmark of hmira.dask.marching_cubes.

scale:   an n^3 float32 gyroid (period 128 samples), generated lazily chunk by chunk by Dask,
         meshed on a LocalCluster of 2 worker processes limited to 2 GiB each, with 128^3 chunks,
         streamed to a PLY. Reports peak RSS per worker (client.run + resource.getrusage), worker
         restarts, wall time, triangles/s, and checks the PLY welded (every edge in at most two
         triangles, and edges in one only on the grid's boundary).
compare: at 512^3, from the same numpy array (generation excluded): hmira.dask on the threaded
         scheduler with 128^3 chunks (and a 2-thread client merge) vs in-memory
         hmira.marching_cubes, at the same thread count; medians of wall and CPU seconds.
"""
import argparse
import json
import os
import resource
import sys
import tempfile
import time

import numpy as np

import dask
import dask.array as da
import hmira
import hmira.dask


def gyroid_block(period, block_info=None):
    (z0, z1), (y0, y1), (x0, x1) = block_info[None]["array-location"]
    w = np.float32(2 * np.pi / period)
    z, y, x = (a.astype(np.float32) * w for a in np.ogrid[z0:z1, y0:y1, x0:x1])
    sx, cx, sy, cy, sz, cz = np.sin(x), np.cos(x), np.sin(y), np.cos(y), np.sin(z), np.cos(z)
    return sx * cy + sy * cz + sz * cx


def lazy_gyroid(n, chunk, period):
    chunks = tuple(tuple(min(chunk, n - s) for s in range(0, n, chunk)) for _ in range(3))
    return da.map_blocks(gyroid_block, period, dtype=np.float32, chunks=chunks)


def peak_rss_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def vm_hwm_mib():
    """The process's own peak RSS (VmHWM). getrusage's ru_maxrss survives fork and exec, so a
    worker spawned by a big client would report the client's peak: run the scale part in a
    fresh process (run.sh does), and read this as well."""
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def read_ply(path):
    with open(path, "rb") as fh:
        head = fh.read(4096)
    end = head.index(b"end_header\n") + len(b"end_header\n")
    lines = head[:end].decode().split("\n")
    nv = int(next(l for l in lines if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in lines if l.startswith("element face")).split()[2])
    v = np.memmap(path, dtype="<f8", mode="r", offset=end, shape=(nv, 3))
    f = np.memmap(path, dtype=np.dtype([("n", "u1"), ("v", "<i4", (3,))]), mode="r", offset=end + 24 * nv, shape=(nf,))
    return v, f


def check_welded(path, n):
    """Every edge in at most two triangles; edges in one triangle only on the grid's boundary."""
    v, f = read_ply(path)
    nv = len(v)
    tri = f["v"]
    key = np.empty(3 * len(tri), dtype=np.int64)
    for c in range(3):  # edge (min, max) as one int64, a column at a time to bound memory
        a, b = tri[:, c].astype(np.int64), tri[:, (c + 1) % 3].astype(np.int64)
        key[c * len(tri):(c + 1) * len(tri)] = np.minimum(a, b) * nv + np.maximum(a, b)
        del a, b
    key.sort()
    starts = np.flatnonzero(np.concatenate([[True], key[1:] != key[:-1]]))
    counts = np.diff(np.concatenate([starts, [len(key)]]))
    if counts.max() > 2:
        return False, f"an edge in {counts.max()} triangles"
    single = key[starts[counts == 1]]
    a, b = single // nv, single % nv
    on_boundary = lambda p: ((p <= 0.0) | (p >= n - 1)).any(axis=1)
    pa, pb = np.asarray(v[np.sort(a)]), np.asarray(v[np.sort(b)])
    ok = bool(on_boundary(pa).all() and on_boundary(pb).all())
    return ok, f"{len(single)} open edges, all on the grid boundary" if ok else "open edges inside the grid"


def scale(n, chunk, period, memory_limit, keep):
    import distributed

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, memory_limit=memory_limit,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        workers_before = set(client.scheduler_info()["workers"])
        field = lazy_gyroid(n, chunk, period)
        out = os.path.join(tempfile.mkdtemp(prefix="hmira-dask-bench-"), "gyroid.ply")
        t0 = time.perf_counter()
        hmira.dask.marching_cubes(field, 0.0, out=out, window=4)
        wall = time.perf_counter() - t0
        client_rss_after_mesh = peak_rss_mib()
        rss = client.run(peak_rss_mib)
        hwm = client.run(vm_hwm_mib)
        workers_after = set(client.scheduler_info()["workers"])
    v, f = read_ply(out)
    nv, nf = len(v), len(f)
    size = os.path.getsize(out)
    welded, why = check_welded(out, n)
    if not keep:
        os.unlink(out)
        os.rmdir(os.path.dirname(out))
    return {
        "n": n, "chunk": chunk, "period": period, "memory_limit": memory_limit,
        "wall_s": round(wall, 2), "vertices": nv, "triangles": nf, "triangles_per_s": round(nf / wall),
        "ply_bytes": size, "worker_peak_rss_mib": {w.rsplit(":", 1)[-1]: round(r, 1) for w, r in rss.items()},
        "worker_vm_hwm_mib": {w.rsplit(":", 1)[-1]: round(r, 1) for w, r in hwm.items()},
        "workers_restarted": workers_before != workers_after, "client_peak_rss_mib_meshing": round(client_rss_after_mesh, 1),
        "client_peak_rss_mib_with_weld_check": round(peak_rss_mib(), 1),
        "welded": welded, "weld_check": why,
    }


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def compare(n, chunk, period, threads, repeats):
    """Wall and CPU seconds of both paths, alternating, `repeats` times each; medians. On a
    shared machine the CPU seconds (user + system, all threads) are the steadier figure."""
    vol = gyroid_block(period, {None: {"array-location": [(0, n)] * 3}})
    darr = da.from_array(vol, chunks=chunk)
    wall_mem, wall_dask, cpu_mem, cpu_dask, cpu_chunk_rows = [], [], [], [], []
    for _ in range(repeats):
        c0, t0 = cpu_seconds(), time.perf_counter()
        ref_v, ref_f = hmira.marching_cubes(vol, 0.0, threads=threads)
        wall_mem.append(time.perf_counter() - t0)
        cpu_mem.append(cpu_seconds() - c0)
        c0, t0 = cpu_seconds(), time.perf_counter()
        with dask.config.set(scheduler="threads", num_workers=threads):
            v, f = hmira.dask.marching_cubes(darr, 0.0, threads=threads)
        wall_dask.append(time.perf_counter() - t0)
        cpu_dask.append(cpu_seconds() - c0)
        same = bool(np.array_equal(v, ref_v) and np.array_equal(f, ref_f))
        del v, f
        # The same direct path with every chunk its own block (before 2026-12-02 18:00), in the same run.
        hmira.dask._DIRECT = "chunk_rows"
        c0 = cpu_seconds()
        try:
            with dask.config.set(scheduler="threads", num_workers=threads):
                v, f = hmira.dask.marching_cubes(darr, 0.0, threads=threads)
        finally:
            hmira.dask._DIRECT = "rows"
        cpu_chunk_rows.append(cpu_seconds() - c0)
        same = same and bool(np.array_equal(v, ref_v) and np.array_equal(f, ref_f))
        triangles = len(ref_f)
        del v, f, ref_v, ref_f
        if not same:
            break
    med = lambda x: float(np.median(x))
    return {"n": n, "chunk": chunk, "threads": threads, "repeats": repeats,
            "in_memory_s": round(med(wall_mem), 3), "dask_threaded_s": round(med(wall_dask), 3),
            "ratio": round(med(wall_dask) / med(wall_mem), 3),
            "ratio_best": round(min(wall_dask) / min(wall_mem), 3),
            "in_memory_cpu_s": round(med(cpu_mem), 3), "dask_cpu_s": round(med(cpu_dask), 3),
            "cpu_ratio": round(med(cpu_dask) / med(cpu_mem), 3),
            "dask_chunk_blocks_cpu_s": round(med(cpu_chunk_rows), 3),
            "chunk_blocks_cpu_ratio": round(med(cpu_chunk_rows) / med(cpu_mem), 3),
            "load": os.getloadavg()[0], "triangles": triangles, "identical": same}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--part", choices=["scale", "compare", "both"], default="both")
    p.add_argument("--n", type=int, default=1024, help="scale: samples per axis")
    p.add_argument("--compare-n", type=int, default=512)
    p.add_argument("--chunk", type=int, default=128)
    p.add_argument("--period", type=float, default=128.0)
    p.add_argument("--memory-limit", default="2GiB")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--keep", action="store_true", help="keep the scale run's PLY")
    a = p.parse_args()
    results = {}
    if a.part in ("compare", "both"):
        results["compare"] = compare(a.compare_n, a.chunk, a.period, a.threads, a.repeats)
        print(json.dumps(results["compare"]), flush=True)
    if a.part in ("scale", "both"):
        results["scale"] = scale(a.n, a.chunk, a.period, a.memory_limit, a.keep)
        print(json.dumps(results["scale"]), flush=True)
    ok = results.get("compare", {}).get("identical", True) and results.get("scale", {}).get("welded", True) and \
        not results.get("scale", {}).get("workers_restarted", False)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
