#!/usr/bin/env python3
"""Chunked voxelization of a real mesh at 2048^3: hmira.dask.voxelize on a
distributed LocalCluster of 2 worker processes limited to 2 GiB each, 256^3 chunks, written to
a zarr v3 store; reports wall time, the store's size, whether any worker restarted, and the
peak RSS of each worker (resource.getrusage through client.run).

usage: dask_zarr.py MESH [--resolution 2048] [--chunk 256] [--mode centres] [--out DIR]
Run it with the venv scripts/python.sh makes (hmira, dask, distributed, zarr installed)."""
import argparse
import os
import resource
import shutil
import tempfile
import time

import numpy as np


def peak_rss_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("--resolution", type=int, default=2048)
    ap.add_argument("--chunk", type=int, default=256)
    ap.add_argument("--mode", default="centres")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()

    import distributed
    import zarr
    import hmira
    from hmira._dask_voxelize import voxelize

    mesh = hmira.read_mesh(a.mesh)
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    # Voxels of this size give `resolution` voxels along the longest side, with hmira's padding.
    pitch = float((v.max(0) - v.min(0)).max()) / (a.resolution - 4)
    out = a.out or tempfile.mkdtemp(prefix="hmira-voxels-")
    store = os.path.join(out, "voxels.zarr")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, memory_limit="2GiB",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        workers_before = set(client.scheduler_info()["workers"])
        grid, origin, pitch = voxelize(v, f, pitch=pitch, chunks=a.chunk, mode=a.mode)
        t0 = time.perf_counter()
        grid.to_zarr(store, compute=True)
        wall = time.perf_counter() - t0
        workers_after = set(client.scheduler_info()["workers"])
        rss = client.run(peak_rss_mib)
    size = sum(os.path.getsize(os.path.join(d, x)) for d, _, files in os.walk(store) for x in files)
    back = zarr.open_array(store, mode="r")
    set_voxels = 0
    for k in range(0, back.shape[2], a.chunk):
        set_voxels += int(np.count_nonzero(back[:, :, k:k + a.chunk]))
    print(f"mesh {os.path.basename(a.mesh)}: {len(f)} triangles, grid {grid.shape}, {grid.numblocks} chunks of {a.chunk}^3, mode {a.mode}")
    print(f"wall {wall:.1f} s, zarr store {size / 2**20:.1f} MiB, {set_voxels} voxels set "
          f"(volume {set_voxels * pitch ** 3:.6g})")
    print(f"workers restarted: {'no' if workers_before == workers_after else 'yes'}")
    for w, mib in sorted(rss.items()):
        print(f"peak RSS {w}: {mib:.0f} MiB (limit 2048 MiB)")
    if a.out is None:
        shutil.rmtree(out)


if __name__ == "__main__":
    main()
