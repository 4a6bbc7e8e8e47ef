"""hmira.dask.decimate and hmira.dask.marching_cubes(..., decimate=...): block-wise decimation on a
fixed grid, welded exactly: the same result for every chunking and worker count, closed and valid
from closed input, near the full-resolution surface; streamed PLY and zarr equal the in-memory
result; a LocalCluster with memory limits, and a worker killed mid-run."""
import os

import numpy as np
import pytest

import hmira

da = pytest.importorskip("dask.array")
dask = pytest.importorskip("dask")
import hmira.dask  # noqa: E402


def gyroid(n, period=16.0):
    x = np.arange(n)[:, None, None] * (2 * np.pi / period)
    y = np.arange(n)[None, :, None] * (2 * np.pi / period)
    z = np.arange(n)[None, None, :] * (2 * np.pi / period)
    return (np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)).astype(np.float32)


def blob(n):
    """A closed surface inside the volume: a sphere with bumps (genus 0)."""
    g = (np.indices((n, n, n)).astype(np.float64) - (n - 1) / 2) / ((n - 1) / 2)
    r = np.sqrt((g ** 2).sum(axis=0))
    return (r - 0.7 - 0.08 * np.sin(5 * g[0]) * np.sin(4 * g[1])).astype(np.float32)


def check_closed_valid(v, f, genus):
    m = hmira.Mesh(v, f)
    t = hmira.mesh_topology(m)
    assert t.closed and t.boundary_edges == 0 and t.non_manifold_edges == 0
    assert t.isolated_vertices == 0
    assert t.genus == genus
    assert m.validate() == []


def volume_of(v, f):
    p = v[f]
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6)


def test_chunkings_give_identical_results():
    vol = blob(24)
    results = []
    for chunks in [(24, 24, 24), (5, 12, 24), (13, 7, 11)]:
        results.append(hmira.dask.marching_cubes(da.from_array(vol, chunks=chunks), 0.0, decimate=0.2, block=8))
    for v, f in results[1:]:
        np.testing.assert_array_equal(v, results[0][0])
        np.testing.assert_array_equal(f, results[0][1])


def test_closed_input_gives_closed_valid_output_near_the_surface():
    vol = blob(34)
    full_v, full_f = hmira.marching_cubes(vol, 0.0)
    v, f = hmira.dask.marching_cubes(da.from_array(vol, chunks=12), 0.0, decimate=0.1, block=16)
    check_closed_valid(v, f, 0)
    # Blocks this small are mostly seams, which pass 2 decimates only up to the error pass 1 reached.
    assert len(f) < 0.4 * len(full_f)
    # The enclosed volume (an independent measure) barely changes, and the surface stays close.
    assert abs(volume_of(v, f) - volume_of(full_v, full_f)) < 0.01 * abs(volume_of(full_v, full_f))
    q = hmira.dask.decimation_quality((full_v, full_f), (v, f), min_samples=20000)
    assert q["hausdorff"] < 1.0 and q["mean"] < 0.1
    assert q["faces"] == len(f) and sum(q["min_angle_histogram"]) == len(f)


def test_gyroid_with_open_boundary_and_genus():
    vol = gyroid(33)
    full_v, full_f = hmira.marching_cubes(vol, 0.0)
    v, f = hmira.dask.marching_cubes(da.from_array(vol, chunks=(16, 9, 33)), 0.0, decimate=0.15, block=16)
    m = hmira.Mesh(v, f)
    assert m.validate() == []
    tf, t = hmira.mesh_topology(hmira.Mesh(full_v, full_f)), hmira.mesh_topology(m)
    # Boundary vertices stay (fix_boundary): the same boundary loops and Euler characteristic.
    assert (t.boundary_loops, t.euler_characteristic, t.non_manifold_edges) == (
        tf.boundary_loops, tf.euler_characteristic, 0)
    assert len(f) < 0.45 * len(full_f)


def test_worker_count_does_not_matter():
    vol = blob(30)
    darr = da.from_array(vol, chunks=15)
    with dask.config.set(scheduler="sync"):
        ref = hmira.dask.marching_cubes(darr, 0.0, decimate={"target_ratio": 0.2, "min_angle": 5}, block=9)
    with dask.config.set(scheduler="threads", num_workers=4):
        got = hmira.dask.marching_cubes(darr, 0.0, decimate={"target_ratio": 0.2, "min_angle": 5}, block=9)
    np.testing.assert_array_equal(got[0], ref[0])
    np.testing.assert_array_equal(got[1], ref[1])


def test_existing_mesh_decimates_to_closed_mesh():
    full_v, full_f = hmira.marching_cubes(blob(30), 0.0)
    v, f = hmira.dask.decimate((full_v, full_f), 0.15, blocks=2)
    check_closed_valid(v, f, 0)
    assert len(f) < 0.6 * len(full_f)
    # The same as a Mesh, and by max_error alone.
    v2, f2 = hmira.dask.decimate(hmira.Mesh(full_v, full_f), 0.15, blocks=2)
    np.testing.assert_array_equal(v2, v)
    np.testing.assert_array_equal(f2, f)
    v3, f3 = hmira.dask.decimate((full_v, full_f), {"max_error": 0.05}, blocks=3)
    check_closed_valid(v3, f3, 0)
    assert len(f3) < len(full_f)


def test_existing_mesh_refuses_blocks_smaller_than_its_triangles():
    full_v, full_f = hmira.marching_cubes(blob(20), 0.0)
    with pytest.raises(ValueError, match="half a block"):
        hmira.dask.decimate((full_v, full_f), 0.5, block_size=0.5)
    with pytest.raises(ValueError, match="target_ratio"):
        hmira.dask.decimate((full_v, full_f), {"min_angle": 3})


def test_streamed_ply_and_zarr_equal_the_in_memory_result(tmp_path):
    zarr = pytest.importorskip("zarr")
    darr = da.from_array(blob(30), chunks=(10, 15, 30))
    v, f = hmira.dask.marching_cubes(darr, 0.0, decimate=0.2, block=9)
    path = tmp_path / "d.ply"
    assert hmira.dask.marching_cubes(darr, 0.0, decimate=0.2, block=9, out=path, zarr=str(tmp_path / "d.zarr")) is None
    m = hmira.read_mesh(str(path), repair=False)
    np.testing.assert_array_equal(np.asarray(m.vertices), v)
    np.testing.assert_array_equal(np.asarray(m.faces), f)
    g = zarr.open_group(str(tmp_path / "d.zarr"), mode="r")
    np.testing.assert_array_equal(g["vertices"][:], v)
    np.testing.assert_array_equal(g["faces"][:], f)


@pytest.fixture(scope="module")
def cluster_client():
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                       memory_limit="512MiB")
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_local_cluster_with_memory_limits_and_a_killed_worker(cluster_client):
    vol = blob(24)
    with dask.config.set(scheduler="sync"):
        ref = hmira.dask.marching_cubes(da.from_array(vol, chunks=12), 0.0, decimate=0.2, block=8)
    darr = da.from_array(vol, chunks=(9, 24, 12))
    v, f = hmira.dask.marching_cubes(darr, 0.0, decimate=0.2, block=8)  # the active Client runs it
    np.testing.assert_array_equal(v, ref[0])
    np.testing.assert_array_equal(f, ref[1])
    for w in cluster_client.scheduler_info()["workers"].values():
        assert w["memory_limit"] == 512 << 20
    # A worker dies while the tasks run (the chunks are made slowly, so the run lasts a few
    # seconds): Dask reruns its tasks elsewhere, the nanny restarts it, and the result is the same.
    import signal
    import threading
    import time

    slow = darr.map_blocks(lambda b: (time.sleep(0.25), b)[1], dtype=darr.dtype)
    before = set(cluster_client.scheduler_info()["workers"])
    victim = sorted(before)[0]

    pid = cluster_client.run(os.getpid, workers=[victim])[victim]

    def kill():
        time.sleep(0.6)
        os.kill(pid, signal.SIGKILL)

    t = threading.Thread(target=kill)
    t.start()
    v2, f2 = hmira.dask.marching_cubes(slow, 0.0, decimate=0.2, block=8)
    t.join()
    np.testing.assert_array_equal(v2, ref[0])
    np.testing.assert_array_equal(f2, ref[1])
    # It did die (and was replaced): the scheduler may take a moment to notice.
    deadline = time.monotonic() + 30
    while victim in set(cluster_client.scheduler_info()["workers"]) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert victim not in set(cluster_client.scheduler_info()["workers"])


def test_block_wise_quality_agrees_with_the_in_memory_measure():
    vol = blob(24)
    full_v, full_f = hmira.marching_cubes(vol, 0.0)
    darr = da.from_array(vol, chunks=12)
    v, f = hmira.dask.marching_cubes(darr, 0.0, decimate=0.1, block=9)
    whole = hmira.dask.decimation_quality((full_v, full_f), (v, f), min_samples=0)
    blocks = hmira.dask.volume_decimation_quality(darr, 0.0, (v, f), block=9, margin=4)
    # Both sample about 10 points per triangle (at other points): the same distances up to sampling.
    assert blocks["full_to_decimated"]["samples"] == pytest.approx(whole["report"]["a_to_b"]["samples"], rel=0.05)
    assert blocks["hausdorff"] == pytest.approx(whole["hausdorff"], rel=0.15)
    assert blocks["mean"] == pytest.approx(whole["mean"], rel=0.05)
    assert blocks["min_angle_histogram"] == whole["min_angle_histogram"]


def test_a_block_goes_on_from_carried_quadrics_as_one_decimation():
    from hmira._dask_decimate import _decimate_block, _options

    full_v, full_f = hmira.marching_cubes(blob(20), 0.0)
    opts, free = _options(0.1), np.zeros(len(full_v), dtype=bool)
    f32 = full_f.astype(np.int32)
    p1, t1, _, _, q1 = _decimate_block(full_v, f32, free, len(f32), len(f32) // 3, opts)
    p2, t2, _, _, _ = _decimate_block(p1, t1, np.zeros(len(p1), dtype=bool), len(t1), len(f32) // 10, opts, q1)
    p3, t3, _, _, _ = _decimate_block(full_v, f32, free, len(f32), len(f32) // 10, opts)
    assert len(t2) == len(t3)
    # The same surviving positions, bit for bit (the rows are numbered differently).
    np.testing.assert_array_equal(np.unique(p2, axis=0), np.unique(p3, axis=0))
    # Starting again from the coarse triangles' own planes gives another mesh.
    p4, _, _, _, _ = _decimate_block(p1, t1, np.zeros(len(p1), dtype=bool), len(t1), len(f32) // 10, opts)
    assert not np.array_equal(np.unique(p4, axis=0), np.unique(p3, axis=0))
