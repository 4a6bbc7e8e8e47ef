"""hmira.dask.marching_cubes: chunked marching cubes on Dask equals hmira.marching_cubes
on the whole array, element for element, for random chunkings, on the threaded scheduler and on a
distributed LocalCluster of several worker processes; streamed PLY output; a zarr v3 round trip."""
import os

import numpy as np
import pytest

import hmira

da = pytest.importorskip("dask.array")
dask = pytest.importorskip("dask")
import hmira.dask  # noqa: E402


def gyroid(n, period=16.0, dtype=np.float32, start=(0, 0, 0)):
    x = np.arange(start[0], start[0] + n[0])[:, None, None] * (2 * np.pi / period)
    y = np.arange(start[1], start[1] + n[1])[None, :, None] * (2 * np.pi / period)
    z = np.arange(start[2], start[2] + n[2])[None, None, :] * (2 * np.pi / period)
    return (np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)).astype(dtype)


def sphere(n):
    g = np.indices(n).astype(np.float64)
    c = (np.array(n, dtype=np.float64) - 1) / 2
    return np.sqrt(((g - c[:, None, None, None]) ** 2).sum(axis=0)) - 0.35 * min(n)


def random_chunks(n, rng, max_chunk=64):
    """Chunk sizes 1..max_chunk summing to n, at most 8 of them (<= 512 blocks per case)."""
    while True:
        m = int(rng.integers(max(1, -(-n // 8)), max_chunk + 1))
        c = []
        while sum(c) < n:
            c.append(int(min(n - sum(c), rng.integers(1, m + 1))))
        if len(c) <= 8:
            return tuple(c)


def canonical(v, f):
    """Vertices sorted, triangles relabelled, rotated to start at their smallest index, sorted."""
    order = np.lexsort(v.T[::-1])
    rank = np.empty(len(v), dtype=np.int64)
    rank[order] = np.arange(len(v))
    t = rank[f]
    r = np.argmin(t, axis=1)
    t = np.stack([t[np.arange(len(t)), (r + s) % 3] for s in range(3)], axis=1)
    return v[order], t[np.lexsort(t.T[::-1])]


KW = dict(spacing=(0.5, 0.75, 1.25), origin=(-3.0, 1.0, 2.5))

FIELDS = {
    "sphere": (lambda: sphere((37, 30, 41)), 0.0, "below"),
    "gyroid": (lambda: gyroid((40, 33, 29)), 0.2, "above"),
    "noise": (lambda: np.random.default_rng(5).uniform(-1, 1, (19, 22, 17)).astype(np.float32), 0.0, "below"),
    # Integers, a third of them exactly at the iso value (as 8-bit scans).
    "at_iso": (lambda: np.random.default_rng(6).integers(0, 3, (21, 18, 24)).astype(np.uint8), 1.0, "above"),
}


@pytest.mark.parametrize("path", ["rows", "chunk_rows", "chunks", "merge"])
@pytest.mark.parametrize("name", sorted(FIELDS))
def test_random_chunkings_equal_whole_volume_threaded(name, path, monkeypatch):
    # In process, chunks write straight into the result ("rows": a task per row of chunks
    # along x, joined into one block; "chunk_rows": a task per row of chunks, each its own
    # block; "chunks": a task per chunk); on other schedulers the client merges keyed chunk
    # meshes ("merge"): all give the whole-volume mesh.
    if path == "merge":
        monkeypatch.setattr(hmira.dask, "_in_process", lambda darr: False)
    else:
        monkeypatch.setattr(hmira.dask, "_DIRECT", path)
        assert hmira.dask._in_process(da.zeros((2, 2, 2)))
    make, iso, inside = FIELDS[name]
    vol = make()
    ref_v, ref_f = hmira.marching_cubes(vol, iso, inside=inside, **KW)
    assert len(ref_f) > 0
    rng = np.random.default_rng(hash(name) % 1000)
    chunkings = [tuple(random_chunks(n, rng) for n in vol.shape) for _ in range(3)]
    # Single-slab chunks along each axis.
    for a in range(3):
        chunkings.append(tuple((1,) * n if b == a else (n,) for b, n in enumerate(vol.shape)))
    with dask.config.set(scheduler="threads"):
        for chunks in chunkings:
            v, f = hmira.dask.marching_cubes(da.from_array(vol, chunks=chunks), iso, inside=inside, **KW)
            assert v.dtype == np.float64 and f.dtype == np.int32
            np.testing.assert_array_equal(v, ref_v, err_msg=str(chunks))
            np.testing.assert_array_equal(f, ref_f, err_msg=str(chunks))


@pytest.mark.parametrize("name", sorted(FIELDS))
def test_rows_of_copied_chunks_equal_whole_volume(name):
    # Chunks that are separate arrays (each a copy, as from zarr or a computed field): the row
    # of chunks along x is copied into one block, with its overlap, and read there.
    make, iso, inside = FIELDS[name]
    vol = make()
    ref_v, ref_f = hmira.marching_cubes(vol, iso, inside=inside, **KW)
    rng = np.random.default_rng(hash(name) % 1000 + 1)
    chunkings = [tuple(random_chunks(n, rng) for n in vol.shape) for _ in range(3)]
    chunkings += [((1,) * vol.shape[0], vol.shape[1], 5), (4, (1,) * vol.shape[1], 7), (3, 5, (1,) * vol.shape[2])]
    assert hmira.dask._DIRECT == "rows"
    with dask.config.set(scheduler="threads"):
        for chunks in chunkings:
            darr = da.from_array(vol, chunks=chunks).map_blocks(np.copy)
            v, f = hmira.dask.marching_cubes(darr, iso, inside=inside, **KW)
            np.testing.assert_array_equal(v, ref_v, err_msg=str(chunks))
            np.testing.assert_array_equal(f, ref_f, err_msg=str(chunks))


def test_rows_too_large_go_a_chunk_per_task(monkeypatch):
    # Above _ROW_BYTES a row of chunks is not joined (its copy would be held per thread): the
    # chunks count and write one by one, with the same result.
    vol = gyroid((30, 26, 33))
    ref_v, ref_f = hmira.marching_cubes(vol, 0.1)
    darr = da.from_array(vol, chunks=(7, 9, 10)).map_blocks(np.copy)
    assert hmira.dask._row_bytes(darr) == 8 * 10 * 33 * 4
    monkeypatch.setattr(hmira.dask, "_ROW_BYTES", 8 * 10 * 33 * 4 - 1)
    monkeypatch.setattr(hmira.dask, "_count_row", None)  # would fail if a row were counted
    with dask.config.set(scheduler="threads"):
        v, f = hmira.dask.marching_cubes(darr, 0.1)
    np.testing.assert_array_equal(v, ref_v)
    np.testing.assert_array_equal(f, ref_f)


def test_join_x_views_only_when_side_by_side():
    # Chunks lying side by side in one array join into a view of it; anything else is copied.
    vol = np.arange(4 * 5 * 12, dtype=np.float32).reshape(4, 5, 12)
    pieces = [vol[1:3, :, 0:5], vol[1:3, :, 5:12]]
    joined = hmira.dask._join_x(pieces)
    assert np.shares_memory(joined, vol) and np.array_equal(joined, vol[1:3])
    apart = [vol[1:3, :, 0:5], vol[1:3, :, 6:12]]  # a gap of one sample
    assert hmira.dask._join_x(apart, copy=False) is None
    copied = hmira.dask._join_x(apart)
    assert not np.shares_memory(copied, vol) and np.array_equal(copied, np.concatenate(apart, axis=2))
    assert hmira.dask._join_x(pieces[::-1], copy=False) is None  # out of order
    assert hmira.dask._join_x([pieces[0], np.asfortranarray(pieces[1])], copy=False) is None  # other strides
    # Side by side only in a one-row array: an array reaching past the chunk's own memory is never made.
    flat = np.arange(10, dtype=np.float32)
    a, b = flat[0:5].reshape(1, 1, 5), flat[5:10].reshape(1, 1, 5)
    assert np.array_equal(hmira.dask._join_x([a, b]), flat.reshape(1, 1, 10))


def test_strided_parts_uint8_and_merge_thread_counts_equal_whole_volume():
    # Chunks that are strided views (a Fortran-ordered source), 8-bit samples at the iso value,
    # one-sample chunks at both ends, and every merge thread count give the whole-volume mesh.
    rng = np.random.default_rng(5)
    vol = rng.integers(0, 3, size=(19, 23, 17)).astype(np.uint8)
    ref_v, ref_f = hmira.marching_cubes(vol, 1.0, inside="above")
    chunks = ((1, 9, 8, 1), (1, 21, 1), (7, 9, 1))
    for source in (vol, np.asfortranarray(vol)):
        for threads in (0, 1, 3):
            v, f = hmira.dask.marching_cubes(da.from_array(source, chunks=chunks), 1.0, inside="above", threads=threads)
            np.testing.assert_array_equal(v, ref_v)
            np.testing.assert_array_equal(f, ref_f)
    with pytest.raises(ValueError, match="threads"):
        hmira.dask.marching_cubes(da.from_array(vol, chunks=8), 1.0, threads=-1)


def test_lazy_field_from_map_blocks_equals_in_memory():
    # The field is made chunk by chunk by Dask; no process holds it whole.
    shape, chunks = (48, 40, 36), (13, 16, 11)

    def block(block_info=None):
        loc = block_info[None]["array-location"]
        return gyroid(tuple(b - a for a, b in loc), start=tuple(a for a, _ in loc))

    lazy = da.map_blocks(block, dtype=np.float32, chunks=tuple(
        tuple(min(c, n - s) for s in range(0, n, c)) for n, c in zip(shape, chunks)))
    v, f = hmira.dask.marching_cubes(lazy, 0.0)
    ref_v, ref_f = hmira.marching_cubes(gyroid(shape), 0.0)
    np.testing.assert_array_equal(v, ref_v)
    np.testing.assert_array_equal(f, ref_f)


@pytest.mark.parametrize("copied", [False, True])
def test_error_in_one_block_names_it(copied):
    vol = gyroid((20, 20, 20))
    vol[15, 3, 17] = np.nan
    darr = da.from_array(vol, chunks=10)
    if copied:
        darr = darr.map_blocks(np.copy)
    with pytest.raises(ValueError, match=r"block \(1, 0, 1\) \(samples \[10:20, 0:10, 10:20\]\).*NaN"):
        hmira.dask.marching_cubes(darr, 0.0)


def test_bad_arguments_are_refused():
    with pytest.raises(ValueError, match="3 dimensions"):
        hmira.dask.marching_cubes(da.zeros((4, 4), chunks=2), 0.0)
    with pytest.raises(ValueError, match="inside must be"):
        hmira.dask.marching_cubes(da.zeros((4, 4, 4), chunks=2), 0.0, inside="up")
    with pytest.raises(ValueError, match="dtype"):
        hmira.dask.marching_cubes(da.zeros((4, 4, 4), chunks=2, dtype=np.int64), 0.0)
    with pytest.raises(ValueError, match="finite"):
        hmira.dask.marching_cubes(da.zeros((4, 4, 4), chunks=2), float("nan"))


def read_ply(path):
    with open(path, "rb") as fh:
        data = fh.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    v = np.frombuffer(data, dtype="<f8", count=3 * nv, offset=end).reshape(nv, 3)
    f = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("v", "<i4", (3,))]), count=nf, offset=end + 24 * nv)
    assert (f["n"] == 3).all()
    assert end + 24 * nv + 13 * nf == len(data)
    return v, f["v"].astype(np.int32)


def test_streamed_ply_is_the_same_mesh(tmp_path):
    vol = gyroid((45, 38, 33))
    ref = canonical(*hmira.marching_cubes(vol, 0.1, **KW))
    path = tmp_path / "out.ply"
    path.write_bytes(b"old")
    assert hmira.dask.marching_cubes(da.from_array(vol, chunks=(10, 17, 9)), 0.1, out=path, window=3, **KW) is None
    v, f = read_ply(path)
    got = canonical(v, f)
    np.testing.assert_array_equal(got[0], ref[0])
    np.testing.assert_array_equal(got[1], ref[1])
    assert sorted(os.listdir(tmp_path)) == ["out.ply"]


def test_failed_stream_leaves_existing_file_and_no_temporaries(tmp_path):
    vol = gyroid((20, 20, 20))
    vol[3, 3, 3] = np.nan
    path = tmp_path / "out.ply"
    path.write_bytes(b"old")
    with pytest.raises(ValueError, match=r"block \(0, 0, 0\)"):
        hmira.dask.marching_cubes(da.from_array(vol, chunks=8), 0.0, out=path)
    assert path.read_bytes() == b"old"
    assert sorted(os.listdir(tmp_path)) == ["out.ply"]


def test_zarr_v3_store_round_trip(tmp_path):
    zarr = pytest.importorskip("zarr")
    assert zarr.__version__.split(".")[0] == "3"
    vol = sphere((34, 29, 31)).astype(np.float32)
    store = zarr.create_array(store=str(tmp_path / "vol.zarr"), shape=vol.shape, chunks=(12, 10, 16), dtype="float32", zarr_format=3)
    store[...] = vol
    back = da.from_zarr(str(tmp_path / "vol.zarr"))
    assert back.chunks[0] == (12, 12, 10)
    v, f = hmira.dask.marching_cubes(back, 0.0, **KW)
    ref_v, ref_f = hmira.marching_cubes(vol, 0.0, **KW)
    np.testing.assert_array_equal(v, ref_v)
    np.testing.assert_array_equal(f, ref_f)


@pytest.fixture(scope="module")
def cluster_client():
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                       memory_limit="1GiB")
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


def test_local_cluster_with_worker_processes(cluster_client, tmp_path):
    assert len(cluster_client.scheduler_info()["workers"]) == 2
    vol = gyroid((41, 36, 30))
    ref_v, ref_f = hmira.marching_cubes(vol, 0.0, **KW)
    darr = da.from_array(vol, chunks=(11, 20, 7))
    v, f = hmira.dask.marching_cubes(darr, 0.0, **KW)  # the active Client runs it
    np.testing.assert_array_equal(v, ref_v)
    np.testing.assert_array_equal(f, ref_f)
    path = tmp_path / "c.ply"
    hmira.dask.marching_cubes(darr, 0.0, out=path, **KW)
    got, ref = canonical(*read_ply(path)), canonical(ref_v, ref_f)
    np.testing.assert_array_equal(got[0], ref[0])
    np.testing.assert_array_equal(got[1], ref[1])
    bad = vol.copy()
    bad[40, 35, 29] = np.nan
    with pytest.raises(ValueError, match=r"block \(3, 1, 4\) \(samples \[33:41, 20:36, 28:30\]\)"):
        hmira.dask.marching_cubes(da.from_array(bad, chunks=(11, 20, 7)), 0.0)


def test_docstring_example_runs():
    import doctest

    runner = doctest.DocTestRunner()
    tests = doctest.DocTestFinder().find(hmira.dask.marching_cubes, globs={})
    assert sum(len(t.examples) for t in tests) >= 4
    for t in tests:
        runner.run(t)
    assert runner.failures == 0


def test_docs_page_example_runs(tmp_path, monkeypatch):
    import pathlib
    import re

    page = pathlib.Path(__file__).resolve().parents[2] / "docs" / "volumes-larger-than-memory.md"
    if not page.exists():
        pytest.skip(f"{page} not found (tests run outside the source tree)")
    blocks = re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S)
    assert blocks
    monkeypatch.chdir(tmp_path)
    for code in blocks:
        exec(compile(code, str(page), "exec"), {})


@pytest.mark.parametrize("name,iso", [("skull_2.9.inr", 2.9), ("liver.inr.gz", 0.5)])
def test_skull_and_liver_chunked_equal_whole_volume(data, name, iso):
    from conftest import read_inr

    vol, spacing = read_inr(data / "images" / name)
    # A C-ordered central crop keeps the run short; random chunks up to 64 samples.
    vol = np.ascontiguousarray(vol[tuple(slice(max(0, (n - 96) // 2), max(0, (n - 96) // 2) + 96) for n in vol.shape)])
    ref_v, ref_f = hmira.marching_cubes(vol, iso, spacing=spacing, inside="above")
    assert len(ref_f) > 1000
    rng = np.random.default_rng(len(name))
    for _ in range(2):
        chunks = tuple(random_chunks(n, rng) for n in vol.shape)
        v, f = hmira.dask.marching_cubes(da.from_array(vol, chunks=chunks), iso, spacing=spacing, inside="above")
        np.testing.assert_array_equal(v, ref_v, err_msg=str(chunks))
        np.testing.assert_array_equal(f, ref_f, err_msg=str(chunks))
