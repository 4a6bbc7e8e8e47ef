"""hmira.marching_cubes: memory orders and dtypes read in place, winding, errors, and agreement
with scikit-image and with the C++ CLI on real volumes."""
import numpy as np
import pytest

import hmira
from conftest import canonical, read_inr, run_cli, signed_volume


def grid(n, lo=-1.5, hi=1.5):
    return np.mgrid[lo:hi:n * 1j, lo:hi:n * 1j, lo:hi:n * 1j]


def sphere(n=48, r=1.0):
    x, y, z = grid(n)
    return np.sqrt(x**2 + y**2 + z**2) - r


def torus(n=64, major=1.0, minor=0.35):
    x, y, z = grid(n)
    return np.sqrt((np.sqrt(x**2 + y**2) - major) ** 2 + z**2) - minor


def ellipsoid(shape=(40, 30, 20)):
    x, y, z = np.meshgrid(*(np.linspace(-1, 1, n) for n in shape), indexing="ij")
    return np.sqrt((x / 0.8) ** 2 + (y / 0.7) ** 2 + (z / 0.6) ** 2) - 1.0


def test_returns_float64_vertices_and_int32_faces_closed_genus_0():
    v, f = hmira.marching_cubes(sphere(), 0.0)
    assert v.dtype == np.float64 and v.shape[1] == 3 and v.flags.c_contiguous
    assert f.dtype == np.int32 and f.shape[1] == 3
    t = hmira.Mesh(v, f).topology()
    assert (t.genus, t.components, t.boundary_loops, t.closed) == (0, 1, 0, True)
    assert len(f) == 2 * len(v) - 4  # Euler: closed genus-0 triangle mesh


@pytest.mark.parametrize("order", ["C", "F"])
def test_winding_is_outward_for_either_memory_order(order):
    vol = np.asarray(ellipsoid(), order=order)
    v, f = hmira.marching_cubes(vol, 0.0)
    # Outward winding encloses a positive volume; the ellipsoid's is 4/3 pi abc in voxel units.
    expected = 4 / 3 * np.pi * (0.8 * 19.5) * (0.7 * 14.5) * (0.6 * 9.5)
    assert signed_volume(v, f) == pytest.approx(expected, rel=0.02)


def test_inside_above_flips_the_orientation():
    vol = ellipsoid()
    v, f = hmira.marching_cubes(vol, 0.0)
    v2, f2 = hmira.marching_cubes(-vol, 0.0, inside="above")
    assert signed_volume(v2, f2) == pytest.approx(signed_volume(v, f), rel=1e-9)


def test_vertex_column_j_is_array_axis_j_with_spacing_and_origin():
    vol = ellipsoid((40, 30, 20))
    v, _ = hmira.marching_cubes(vol, 0.0, spacing=(1.0, 2.0, 3.0), origin=(10.0, 20.0, 30.0))
    lo, hi = v.min(axis=0), v.max(axis=0)
    centre = (lo + hi) / 2
    np.testing.assert_allclose(centre, [10 + 19.5, 20 + 2 * 14.5, 30 + 3 * 9.5], atol=0.05)
    # Half-extents: semi-axes 0.8, 0.7, 0.6 of the unit box mapped to 19.5, 14.5*2, 9.5*3.
    np.testing.assert_allclose((hi - lo) / 2, [0.8 * 19.5, 0.7 * 29, 0.6 * 28.5], rtol=0.03)


def test_c_fortran_and_strided_inputs_give_the_same_surface():
    vol = ellipsoid()
    ref_v, ref_f = hmira.marching_cubes(np.ascontiguousarray(vol), 0.0)
    big = np.zeros((80, 60, 40))
    big[::2, ::2, ::2] = vol
    for candidate in (np.asfortranarray(vol), big[::2, ::2, ::2], np.ascontiguousarray(vol[::-1])[::-1]):
        v, f = hmira.marching_cubes(candidate, 0.0)
        assert len(f) == len(ref_f)
        np.testing.assert_allclose(np.sort(v, axis=0), np.sort(ref_v, axis=0), atol=1e-12)
        assert signed_volume(v, f) == pytest.approx(signed_volume(ref_v, ref_f), rel=1e-3)


def test_input_is_read_in_place_not_copied():
    vol = np.ascontiguousarray(ellipsoid(), dtype=np.float32)
    vol.flags.writeable = False  # a copy would be allowed too, but nothing may write to it
    before = vol.copy()
    hmira.marching_cubes(vol, 0.0)
    np.testing.assert_array_equal(vol, before)


@pytest.mark.parametrize("dtype,iso", [(np.float32, 0.0), (np.float64, 0.0), (np.uint8, 100.5), (np.uint16, 1000.5), (np.int16, 0.5)])
def test_every_supported_dtype(dtype, iso):
    base = ellipsoid()
    if np.issubdtype(dtype, np.integer):
        scale = {np.uint8: 100, np.uint16: 1000, np.int16: 1000}[dtype]
        offset = 0 if dtype is np.int16 else scale
        vol = np.clip(np.round(-base * scale + offset), np.iinfo(dtype).min, np.iinfo(dtype).max).astype(dtype)
        v, f = hmira.marching_cubes(vol, iso, inside="above")
    else:
        v, f = hmira.marching_cubes(base.astype(dtype), iso)
    assert len(f) > 1000 and signed_volume(v, f) > 0
    assert hmira.Mesh(v, f).topology().closed


def test_bad_inputs_raise_value_error_with_the_message():
    vol = ellipsoid()
    vol[5, 6, 7] = np.nan
    with pytest.raises(ValueError, match="NaN"):
        hmira.marching_cubes(vol, 0.0)
    with pytest.raises(ValueError, match="inside"):
        hmira.marching_cubes(ellipsoid(), 0.0, inside="sideways")
    with pytest.raises(ValueError, match="spacing"):
        hmira.marching_cubes(ellipsoid(), 0.0, spacing=(1.0, -1.0, 1.0))
    with pytest.raises(ValueError, match="finite"):
        hmira.marching_cubes(ellipsoid(), np.inf)
    with pytest.raises(ValueError, match="dtype"):
        hmira.marching_cubes(ellipsoid().astype(np.complex128), 0.0)
    with pytest.raises(TypeError):
        hmira.marching_cubes(np.zeros((4, 4)), 0.0)


def test_thread_count_does_not_change_the_output():
    vol = torus(48)
    v1, f1 = hmira.marching_cubes(vol, 0.0, threads=1)
    v0, f0 = hmira.marching_cubes(vol, 0.0, threads=0)
    np.testing.assert_array_equal(v1, v0)
    np.testing.assert_array_equal(f1, f0)


# ---- against scikit-image ----------------------------------------------------------------------

def clamped_or_centre(v, vol_shape):
    """Vertices hmira may place differently from scikit-image: those within the 1/512 clamp of a
    sample along their edge, and the extra centre vertices of ambiguous cells (off every edge)."""
    frac = v - np.floor(v)
    on_edge = (np.sum(frac > 1e-9, axis=1) == 1)
    near_sample = np.any((frac > 1e-9) & ((frac <= 1 / 512 + 1e-9) | (frac >= 1 - 1 / 512 - 1e-9)), axis=1)
    return ~on_edge | near_sample


@pytest.mark.parametrize("name,vol", [("sphere", sphere(48)), ("torus", torus(64))])
def test_agrees_with_scikit_image(name, vol):
    measure = pytest.importorskip("skimage.measure")
    v, f = hmira.marching_cubes(vol, 0.0)
    sv, sf, _, _ = measure.marching_cubes(vol, 0.0, method="lorensen")
    assert len(f) == len(sf), name
    keep = ~clamped_or_centre(v, vol.shape)
    ours = np.unique(np.round(v[keep], 6), axis=0)
    theirs = np.unique(np.round(sv.astype(np.float64), 6), axis=0)
    # Every hmira vertex off the clamp has a scikit-image vertex within 1e-6 (float32 output there:
    # compare at its precision, 1e-6 relative to the coordinate).
    from scipy.spatial import cKDTree

    d, _ = cKDTree(theirs).query(ours)
    assert np.all(d <= 1e-6 * np.maximum(1.0, np.abs(ours).max(axis=1)) * 4), d.max()
    assert abs(signed_volume(v, f)) == pytest.approx(abs(signed_volume(sv.astype(np.float64), sf)), rel=1e-3)


# ---- against the C++ CLI on real volumes ------------------------------------------------------------

@pytest.mark.parametrize("name,iso,inside", [("skull_2.9.inr", 2.9, "above"), ("liver.inr.gz", 0.5, "above")])
def test_real_volume_matches_the_cli_after_relabelling(data, cli, tmp_path, name, iso, inside):
    vol, spacing = read_inr(data / "images" / name)
    v, f = hmira.marching_cubes(vol, iso, spacing=spacing, inside=inside)
    assert len(f) > 1000
    out = tmp_path / "cli.off"
    run_cli(cli, "mc", data / "images" / name, out, "--iso", iso, "--inside", inside, "-q")
    cm = hmira.read_mesh(out)
    cv, cf = canonical(np.array(cm.vertices), cm.polygons)
    pv, pf = canonical(v, f.tolist())
    assert pf == cf
    np.testing.assert_allclose(pv, cv, rtol=1e-12, atol=1e-9)
