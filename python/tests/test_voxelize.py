"""hmira.voxelize: the grid's layout, voxel counts against analytic volumes, options, errors,
and agreement with the C++ CLI on real meshes."""
import numpy as np
import pytest

import hmira
from conftest import run_cli


def sphere_mesh(r=1.0, n=96):
    x, y, z = np.mgrid[-1.5:1.5:n * 1j, -1.5:1.5:n * 1j, -1.5:1.5:n * 1j]
    v, f = hmira.marching_cubes(np.sqrt(x**2 + y**2 + z**2) - r, 0.0, spacing=(3 / (n - 1),) * 3, origin=(-1.5,) * 3)
    return v, f


def box_mesh(a=2.0, b=1.0, c=0.5):
    v = np.array([[0, 0, 0], [a, 0, 0], [a, b, 0], [0, b, 0], [0, 0, c], [a, 0, c], [a, b, c], [0, b, c]], dtype=float)
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return v, f


def test_grid_layout_origin_and_pitch():
    v, f = box_mesh()
    grid, origin, pitch = hmira.voxelize(v, f, resolution=20)
    assert grid.dtype == np.bool_ and grid.ndim == 3
    assert pitch == pytest.approx(0.1)
    # 20 x 10 x 5 voxels plus two padding layers on each side, indexed [x, y, z].
    assert grid.shape == (24, 14, 9)
    # Centre of voxel [i, j, k] is origin + pitch * (i, j, k): the box spans 0..2 along x.
    np.testing.assert_allclose(origin + pitch * 2, [0.05, 0.05, 0.05], atol=1e-12)
    assert not grid[0].any() and not grid[-1].any() and not grid[:, :, 0].any()


def test_solid_box_fills_its_voxels_and_nothing_beyond_the_first_padding_layer():
    v, f = box_mesh()
    grid, _, pitch = hmira.voxelize(v, f, resolution=20, mode="conservative")
    # The box covers voxels 2..21 x 2..11 x 2..6 exactly; its faces lie on voxel boundaries, so
    # the voxels just outside touch it too and may be set (the first padding layer), no further.
    assert grid[2:22, 2:12, 2:7].all()
    assert grid.sum() - grid[1:23, 1:13, 1:8].sum() == 0
    assert 20 * 10 * 5 <= grid.sum() <= 22 * 12 * 7
    surface, _, _ = hmira.voxelize(v, f, resolution=20, mode="surface")
    assert not surface[3:21, 3:11, 3:6].any() and surface[2:22, 2:12, 2].all()


@pytest.mark.parametrize("resolution", [32, 64])
def test_solid_sphere_count_approaches_the_analytic_volume(resolution):
    v, f = sphere_mesh()
    grid, _, pitch = hmira.voxelize(v, f, resolution=resolution)
    surface, _, _ = hmira.voxelize(v, f, resolution=resolution, mode="surface")
    inside_only = grid.sum() - surface.sum()
    analytic = 4 / 3 * np.pi  # r = 1
    # Conservative: the solid count over-estimates, the strictly inside count under-estimates.
    assert inside_only * pitch**3 < analytic < grid.sum() * pitch**3
    assert grid.sum() * pitch**3 == pytest.approx(analytic, rel=12 / resolution)


def test_pitch_instead_of_resolution_and_mesh_inputs():
    v, f = sphere_mesh()
    extent = (v.max(axis=0) - v.min(axis=0)).max()
    a, oa, pa = hmira.voxelize(v, f, pitch=extent / 20)
    b, ob, pb = hmira.voxelize(hmira.Mesh(v, f), resolution=20)
    assert pa == pytest.approx(pb) and a.shape == b.shape
    np.testing.assert_array_equal(a, b)
    np.testing.assert_allclose(oa, ob, atol=1e-9)


def test_open_mesh_fills_only_with_fill_open():
    v, f = sphere_mesh()
    open_f = f[10:]  # a small hole
    surface_only, _, _ = hmira.voxelize(v, open_f, resolution=20)
    closed, _, _ = hmira.voxelize(v, f, resolution=20)
    filled, _, _ = hmira.voxelize(v, open_f, resolution=20, fill_open=True)
    assert surface_only.sum() < filled.sum() <= closed.sum()
    assert filled.sum() > 0.95 * closed.sum()


def test_default_resolution_is_256_like_the_cli():
    v, f = box_mesh(1, 1, 1)
    grid, _, pitch = hmira.voxelize(v, f, mode="surface")
    assert pitch == pytest.approx(1 / 256) and grid.shape == (260, 260, 260)


def test_bad_arguments_raise_value_error():
    v, f = box_mesh()
    with pytest.raises(ValueError, match="mode"):
        hmira.voxelize(v, f, mode="centres-ish")
    with pytest.raises(ValueError, match="not both"):
        hmira.voxelize(v, f, resolution=8, pitch=0.1)
    with pytest.raises(ValueError, match="out of range"):
        hmira.voxelize(v, [[0, 1, 99]])
    bad = v.copy()
    bad[2, 1] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        hmira.voxelize(bad, f)


@pytest.mark.parametrize("name,surface", [("bunny00.off", False), ("anchor.off", True), ("cactus.off", False)])
def test_real_mesh_matches_the_cli(data, cli, tmp_path, name, surface):
    path = data / "meshes" / name
    mesh = hmira.read_mesh(path)
    grid, origin, pitch = hmira.voxelize(mesh, resolution=48, mode="surface" if surface else "conservative")
    out = tmp_path / "v.raw"
    args = ["voxelize", path, out, "-n", "48", "-q", "--mode", "surface" if surface else "conservative"]
    run_cli(cli, *args)
    sidecar = dict(line.split(": ", 1) for line in (tmp_path / "v.raw.txt").read_text().splitlines() if ": " in line and not line.startswith("#"))
    dims = [int(x) for x in sidecar["dims"].split(",")]
    cli_grid = np.fromfile(out, dtype=np.uint8).reshape(dims, order="F").astype(bool)
    assert grid.shape == tuple(dims)
    np.testing.assert_array_equal(grid, cli_grid)
    np.testing.assert_allclose(origin, [float(x) for x in sidecar["origin"].split()[0].split(",")], rtol=1e-12)


@pytest.mark.parametrize("name", ["sphere", "bunny00.off", "elephant.off", "cheese.off", "fandisk.off"])
def test_faces_read_in_place_give_the_same_voxels_as_the_mesh_path(data, name):
    # (m, k) int32/int64 face arrays are voxelized in place, without building a mesh; a list of
    # polygons still goes through a soup and a face_vertex_mesh (the path every input took
    # before). Every mode must give the same grid either way.
    if name == "sphere":
        v, f = sphere_mesh(n=48)
    else:
        path = data / "meshes" / name
        if not path.exists():
            pytest.skip(f"{name} not in the test data")
        m = hmira.read_mesh(path)
        v, f = np.array(m.vertices), m.faces
    polygons = [list(map(int, row)) for row in f]
    extent = float(np.ptp(v, axis=0).max())
    for options in (dict(resolution=48), dict(resolution=40, mode="surface"), dict(resolution=31, fill_open=True),
                    dict(pitch=extent / 29)):
        want = hmira.voxelize(v, polygons, **options)
        for faces in (np.ascontiguousarray(f, dtype=np.int32), np.ascontiguousarray(f, dtype=np.int64)):
            got = hmira.voxelize(v, faces, **options)
            assert np.array_equal(got[0], want[0]), (name, options, faces.dtype)
            assert np.array_equal(got[1], want[1]) and got[2] == want[2]


def test_faces_read_in_place_are_checked():
    v, f = sphere_mesh(n=16)
    bad = np.array(f, dtype=np.int64)
    bad[7, 2] = len(v)
    with pytest.raises(ValueError, match=f"voxelize: face 7 uses vertex {len(v)}, out of range"):
        hmira.voxelize(v, bad, resolution=8)
    bad[7, 2] = -1
    with pytest.raises(ValueError, match="voxelize: face 7 uses vertex -1, out of range"):
        hmira.voxelize(v, bad.astype(np.int32), resolution=8)
    nan = v.copy()
    nan[3, 1] = np.nan
    with pytest.raises(ValueError, match="voxelize: vertex 3 has a non-finite coordinate"):
        hmira.voxelize(nan, f, resolution=8)
