"""hmira.dask.voxelize (python/hmira/_dask_voxelize.py): chunked voxelization equal to
hmira.voxelize voxel for voxel, for every mode and random chunkings, on the threaded scheduler
and a distributed LocalCluster; written to zarr and read back; errors name the chunk."""
from __future__ import annotations

import numpy as np
import pytest

import hmira
from hmira.dask import voxelize as dask_voxelize

da = pytest.importorskip("dask.array")


@pytest.fixture(scope="module")
def elephant(data):
    mesh = hmira.read_mesh(str(data / "meshes" / "elephant.off"))
    return np.asarray(mesh.vertices), np.asarray(mesh.faces)


@pytest.mark.parametrize("mode", ["centres", "conservative", "surface"])
def test_random_chunkings_equal_the_whole_grid(elephant, mode):
    v, f = elephant
    extent = (v.max(0) - v.min(0)).max()
    pitch = extent / 64
    whole, origin, p = hmira.voxelize(v, f, pitch=pitch, mode=mode)
    rng = np.random.default_rng(3)
    chunkings = [(13, 64, 7), (70, 70, 1), tuple(int(c) for c in rng.integers(1, 40, size=3)), whole.shape]
    for chunks in chunkings:
        grid, o, q = dask_voxelize(v, f, pitch=pitch, chunks=chunks, mode=mode)
        assert np.array_equal(o, origin) and q == p
        assert grid.shape == whole.shape and grid.dtype == bool
        got = grid.compute(scheduler="threads")
        assert np.array_equal(got, whole), f"chunks {chunks}"


def test_distributed_local_cluster_and_zarr_round_trip(elephant, tmp_path):
    distributed = pytest.importorskip("distributed")
    zarr = pytest.importorskip("zarr")
    v, f = elephant
    pitch = (v.max(0) - v.min(0)).max() / 48
    whole, _, _ = hmira.voxelize(v, f, pitch=pitch, mode="centres")
    grid, _, _ = dask_voxelize(v, f, pitch=pitch, chunks=(20, 24, 16), mode="centres")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        store = str(tmp_path / "voxels.zarr")
        grid.to_zarr(store, compute=True)
        got = client.compute(grid).result()
    assert np.array_equal(got, whole)
    back = zarr.open_array(store, mode="r")
    assert back.dtype == bool
    assert np.array_equal(back[...], whole)


def test_an_error_names_the_chunk(elephant):
    v, f = elephant
    bad = f.copy()
    bad[5] = [0, 0, 1]  # a face using vertex 0 twice
    grid, _, _ = dask_voxelize(v, bad, pitch=(v.max(0) - v.min(0)).max() / 16, chunks=8)
    with pytest.raises(ValueError, match=r"hmira.dask.voxelize: block \(\d+, \d+, \d+\) \(voxels \[\d+:\d+, \d+:\d+, \d+:\d+\]\): "
                                         r"voxelize: a face uses vertex 0 twice"):
        grid.compute(scheduler="threads")
    with pytest.raises(ValueError, match="mode must be"):
        dask_voxelize(v, f, pitch=0.1, chunks=8, mode="centre")
