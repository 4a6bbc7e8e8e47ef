"""hmira.dask.signed_distance (python/hmira/_dask_sdf.py): every chunking gives exactly the
in-memory hmira.signed_distance at the grid's samples (computed here from numpy positions),
on the grid hmira.dask.voxelize places; the engine is built once per process and shared by
the chunks; the sign follows the winding number; errors name the chunk or the argument."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import hmira
from hmira.dask import signed_distance as dask_sdf
from hmira.dask import voxelize as dask_voxelize

da = pytest.importorskip("dask.array")


@pytest.fixture(scope="module")
def elephant(data):
    mesh = hmira.read_mesh(str(data / "meshes" / "elephant.off"))
    return np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces)


def samples(origin, pitch, shape):
    i, j, k = np.meshgrid(*(np.arange(n, dtype=np.float64) for n in shape), indexing="ij")
    return np.stack([origin[0] + i * pitch, origin[1] + j * pitch, origin[2] + k * pitch], axis=-1).reshape(-1, 3)


def test_random_chunkings_equal_the_in_memory_query(elephant):
    v, f = elephant
    pitch = float((v.max(0) - v.min(0)).max()) / 24
    _, vox_origin, vox_pitch = dask_voxelize(v, f, pitch=pitch, chunks=8)
    grid, origin, p = dask_sdf(v, f, pitch=pitch, chunks=(7, 24, 5))
    assert np.array_equal(origin, vox_origin) and p == vox_pitch
    whole = hmira.signed_distance(v, f, samples(origin, p, grid.shape)).reshape(grid.shape)
    assert (whole < 0).any() and (whole > 0).any()
    rng = np.random.default_rng(5)
    for chunks in [(7, 24, 5), tuple(int(c) for c in rng.integers(1, 16, size=3)), grid.shape]:
        g, _, _ = dask_sdf(v, f, pitch=pitch, chunks=chunks)
        assert g.dtype == np.float64 and g.shape == whole.shape
        got = g.compute(scheduler="threads")
        assert np.array_equal(got, whole), f"chunks {chunks}"


def test_sign_modes_and_chunkings_agree(elephant):
    v, f = elephant
    pitch = float((v.max(0) - v.min(0)).max()) / 10
    for sign in ["parity", "pseudo_normal"]:
        g, origin, p = dask_sdf(v, f, pitch=pitch, chunks=4, sign=sign)
        want = hmira.signed_distance(v, f, samples(origin, p, g.shape), sign=sign).reshape(g.shape)
        assert np.array_equal(g.compute(scheduler="threads"), want)
    g, _, _ = dask_sdf(v, f, pitch=pitch, chunks=4)
    assert np.array_equal(g.compute(scheduler="threads"),
                          dask_sdf(v, f, pitch=pitch, chunks=g.shape)[0].compute(scheduler="threads"))


def test_the_chunks_share_one_engine_and_the_task_pickles_without_it(elephant, monkeypatch):
    import hmira._dask_sdf as mod

    v, f = elephant
    built = []
    real = mod._core._SignedDistanceEngine

    class Counting:
        def __init__(self, *args, **kwargs):
            built.append(1)
            self.inner = real(*args, **kwargs)

        def block(self, **kwargs):
            return self.inner.block(**kwargs)

    monkeypatch.setattr(mod._core, "_SignedDistanceEngine", Counting)
    g, _, _ = dask_sdf(v, f, pitch=float((v.max(0) - v.min(0)).max()) / 10, chunks=3)
    assert g.numblocks[0] * g.numblocks[1] * g.numblocks[2] > 8
    g.compute(scheduler="threads")
    assert len(built) == 1
    task = mod._Block(v, f, (0.0, 0.0, 0.0), 1.0, "winding_number", 2.0, 1)
    first = task.engine()
    assert task.engine() is first
    copy = pickle.loads(pickle.dumps(task))
    assert copy._engine is None and copy.engine() is not first


def test_bad_arguments_and_chunk_errors(elephant):
    v, f = elephant
    with pytest.raises(ValueError, match="faces"):
        dask_sdf(v, f[:, :2], pitch=1.0)
    with pytest.raises(ValueError, match="beta"):
        dask_sdf(v, f, pitch=1.0, beta=0.5)
    with pytest.raises(ValueError, match="sign"):
        dask_sdf(v, f, pitch=1.0, sign="guess")
    bad = f.copy()
    bad[0, 0] = len(v) + 5
    g, _, _ = dask_sdf(v, bad, pitch=float((v.max(0) - v.min(0)).max()) / 4, chunks=2)
    with pytest.raises(ValueError, match=r"block \(\d+, \d+, \d+\) \(samples \[.*vertex"):
        g.compute(scheduler="synchronous")
