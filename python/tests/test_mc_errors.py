"""hmira.marching_cubes and hmira.dask.marching_cubes refuse what would give a wrong or empty
mesh: a NaN or infinite sample (ValueError naming it, never a non-finite vertex) and an iso
value outside the samples' range (ValueError naming the range, never an empty result)."""
import re

import numpy as np
import pytest

import hmira
from conftest import read_inr


def sphere(n=20):
    x, y, z = np.mgrid[-1:1:n * 1j, -1:1:n * 1j, -1:1:n * 1j]
    return np.sqrt(x**2 + y**2 + z**2) - 0.6


@pytest.mark.parametrize("bad, word", [(np.inf, "inf"), (-np.inf, "-inf"), (np.nan, "NaN")])
@pytest.mark.parametrize("order", ["C", "F"])
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_a_non_finite_sample_raises_naming_it_by_its_array_index(bad, word, order, dtype):
    vol = np.asarray(sphere(), dtype=dtype, order=order)
    vol[3, 11, 17] = bad
    with pytest.raises(ValueError, match=r"volume\[3, 11, 17\] is " + word + "; every sample must be finite"):
        hmira.marching_cubes(vol, 0.0)


def test_a_non_finite_sample_of_a_strided_view_raises_naming_it():
    vol = sphere(24)
    vol[4, 6, 8] = np.inf
    view = vol[::2, ::2, ::2]  # strided: neither C nor Fortran contiguous
    with pytest.raises(ValueError, match=r"volume\[2, 3, 4\] is inf"):
        hmira.marching_cubes(view, 0.0)


def test_finite_volumes_give_finite_vertices():
    v, f = hmira.marching_cubes(sphere(), 0.0)
    assert len(f) > 0 and np.isfinite(v).all()


@pytest.mark.parametrize("dtype", [np.uint8, np.int16, np.float32])
def test_an_iso_outside_the_range_raises_naming_the_range(dtype):
    vol = np.full((10, 11, 12), 12, dtype=dtype)
    vol[3:7, 4:8, 2:9] = 40
    for iso, inside in [(0.0, "below"), (0.0, "above"), (41.0, "above"), (300.0, "below")]:
        with pytest.raises(ValueError, match=r"iso \S+ is outside the samples' range \[12, 40\]"):
            hmira.marching_cubes(vol, iso, inside=inside)
    v, f = hmira.marching_cubes(vol, 26.0, inside="above")
    assert len(f) > 0
    # The ends of the range are accepted, even where every sample lies on one side.
    v, f = hmira.marching_cubes(vol, 40.0, inside="below")
    assert len(f) == 0


def test_the_skull_at_iso_0_raises_and_at_the_default_and_the_gallery_iso_meshes(data):
    vol, spacing = read_inr(data / "images" / "skull_2.9.inr")
    lo, hi = float(vol.min()), float(vol.max())
    assert lo > 0  # iso 0 lies below every sample
    with pytest.raises(ValueError, match=r"iso 0 is outside the samples' range \[" + re.escape(repr(lo).removesuffix(".0"))):
        hmira.marching_cubes(vol, 0.0, spacing=spacing)
    v, f = hmira.marching_cubes(vol, spacing=spacing, inside="above")  # the default: the range's midpoint
    ref_v, ref_f = hmira.marching_cubes(vol, lo / 2 + hi / 2, spacing=spacing, inside="above")
    assert len(f) > 0 and np.array_equal(v, ref_v) and np.array_equal(f, ref_f)
    v, f = hmira.marching_cubes(vol, 2.9, spacing=spacing, inside="above")
    assert len(f) > 0 and np.isfinite(v).all()


def test_dask_refuses_infinite_samples_and_an_iso_outside_the_range(tmp_path):
    da = pytest.importorskip("dask.array")
    import hmira.dask

    vol = sphere(20).astype(np.float32)
    vol[13, 2, 5] = np.inf
    darr = da.from_array(vol, chunks=8)
    with pytest.raises(ValueError, match=r"is inf; every sample must be finite"):
        hmira.dask.marching_cubes(darr, 0.0)
    with pytest.raises(ValueError, match=r"is inf"):
        hmira.dask.marching_cubes(darr, 0.0, out=tmp_path / "bad.ply")
    assert not (tmp_path / "bad.ply").exists()

    far = da.from_array(sphere(20).astype(np.float32) + 5.0, chunks=8)  # every sample above 0
    lo, hi = float(far.min().compute()), float(far.max().compute())
    with pytest.raises(ValueError, match=r"iso 0 is outside the samples' range \["):
        hmira.dask.marching_cubes(far, 0.0)
    with pytest.raises(ValueError, match=r"outside the samples' range"):
        hmira.dask.marching_cubes(far, 0.0, out=tmp_path / "empty.ply")
    assert not (tmp_path / "empty.ply").exists()
    with pytest.raises(ValueError, match=r"outside the samples' range"):
        hmira.dask.marching_cubes(far, hi + 1.0, inside="above")
    # Inside the range, with no surface (every sample inside): no error, no triangles.
    v, f = hmira.dask.marching_cubes(far, hi)
    assert len(f) == 0
    v, f = hmira.dask.marching_cubes(far, (lo + hi) / 2)
    assert len(f) > 0
