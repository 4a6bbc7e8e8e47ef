"""The package's everyday basics, each checked by an independent route: marching cubes' default
iso and input dtypes, explicit repair on reading, strict construction from trimesh, the Mesh
geometry measures (against numpy and analytic values), split, transforms, pickling, vertex
colours, read_volume, and the one vocabulary of option names."""
from __future__ import annotations

import pickle
import subprocess
import types
import warnings

import numpy as np
import pytest

import hmira
from conftest import read_inr, run_cli, signed_volume


def ball(n=24, r=0.6):
    x, y, z = np.mgrid[-1:1:n * 1j, -1:1:n * 1j, -1:1:n * 1j]
    return np.sqrt(x**2 + y**2 + z**2) - r


CUBE_V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
CUBE_F = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def box(size=(1.0, 1.0, 1.0), at=(0.0, 0.0, 0.0)):
    return hmira.Mesh(np.array(CUBE_V, dtype=float) * size + at, CUBE_F)


def triangles(m):
    return np.asarray(m.vertices, dtype=float), np.asarray(m.faces)


# --- marching cubes: never an empty mesh by default, every dtype ---------------------------------


def test_default_iso_is_the_midpoint_of_the_data_range():
    vol = ball()
    mid = (vol.min() + vol.max()) / 2
    v0, f0 = hmira.marching_cubes(vol)
    v1, f1 = hmira.marching_cubes(vol, float(vol.min() / 2 + vol.max() / 2))
    assert len(f0) > 0
    assert np.array_equal(v0, v1) and np.array_equal(f0, f1)
    # every vertex interpolates between samples on both sides of the midpoint
    assert vol.min() < mid < vol.max()


def test_a_scan_like_volume_at_the_default_iso_is_not_empty():
    # A CT-like volume (all positive): iso 0 would have no surface at all.
    scan = (1000 - 800 * (ball() < 0)).astype(np.int16)
    v, f = hmira.marching_cubes(scan, inside="above")
    assert len(f) > 0 and hmira.Mesh(v, f).volume() < 0  # the dark ball is the solid: inside-out at "above"
    v, f = hmira.marching_cubes(scan)  # at "below" the ball (200) is the solid
    assert hmira.Mesh(v, f).volume() > 0


def test_an_iso_outside_the_range_names_the_range():
    vol = (ball() * 10).astype(np.float32)
    lo, hi = float(vol.min()), float(vol.max())
    with pytest.raises(ValueError, match=r"outside the samples' range \[") as e:
        hmira.marching_cubes(vol, hi + 1)
    assert repr(lo)[:4] in str(e.value) or f"{lo:g}"[:4] in str(e.value)
    with pytest.raises(ValueError, match="outside"):
        hmira.marching_cubes(vol, lo - 1)


def test_a_constant_volume_raises_instead_of_returning_nothing():
    with pytest.raises(ValueError, match="outside|no surface"):
        hmira.marching_cubes(np.zeros((4, 4, 4)), 1.0)


@pytest.mark.parametrize("dtype", [np.int8, np.int32, np.int64, np.uint32, np.uint64, np.int16, np.uint8])
def test_integer_label_maps_give_the_float_result(dtype):
    labels = (ball() < 0).astype(dtype) * 3
    v, f = hmira.marching_cubes(labels, 1.5, inside="above")
    ref_v, ref_f = hmira.marching_cubes(labels.astype(np.float64), 1.5, inside="above")
    assert len(f) > 0 and np.array_equal(v, ref_v) and np.array_equal(f, ref_f)


def test_bool_volumes_and_nested_lists():
    mask = ball() < 0
    v, f = hmira.marching_cubes(mask, 0.5, inside="above")
    ref_v, ref_f = hmira.marching_cubes(mask.astype(np.float64), 0.5, inside="above")
    assert np.array_equal(v, ref_v) and np.array_equal(f, ref_f)
    # the default iso of a bool mask is 0.5
    v2, f2 = hmira.marching_cubes(mask, inside="above")
    assert np.array_equal(v2, ref_v)
    lv, lf = hmira.marching_cubes(mask.astype(int).tolist(), 0.5, inside="above")
    assert np.array_equal(lv, ref_v) and np.array_equal(lf, ref_f)
    with pytest.raises(ValueError):
        hmira.marching_cubes([[[0, 1], [1]], [[0, 1], [1, 0]]], 0.5)


# --- repair is explicit -----------------------------------------------------------------------


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for p in vertices:
            f.write(" ".join(map(str, p)) + "\n")
        for face in faces:
            f.write(f"{len(face)} " + " ".join(map(str, face)) + "\n")


# Three triangles on the edge (0, 1): no half-edge mesh holds it as it is.
FIN_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
FIN_F = [[0, 1, 2], [1, 0, 3], [0, 1, 4]]


def test_read_mesh_reports_what_it_repaired(tmp_path):
    path = tmp_path / "fin.off"
    write_off(path, FIN_V, FIN_F)
    with pytest.warns(hmira.RepairWarning, match="repaired for editing"):
        m = hmira.read_mesh(path)
    assert m.repairs and m.vertex_count > len(FIN_V)  # a copy of a vertex of the third face
    with pytest.raises(ValueError, match="face"):
        hmira.read_mesh(path, repair=False)


def test_a_clean_file_is_read_silently(tmp_path):
    path = tmp_path / "cube.off"
    write_off(path, CUBE_V, CUBE_F)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        m = hmira.read_mesh(path)
    assert m.repairs == "" and m.vertex_count == 8
    assert hmira.read_mesh(path, repair=False).face_count == 6


def test_pig_stl_repair_matches_what_validate_reports(data):
    path = data / "meshes" / "pig.stl"
    with pytest.warns(hmira.RepairWarning):
        m = hmira.read_mesh(path)
    assert "split" in m.repairs or "vertex" in m.repairs
    with pytest.raises(ValueError):
        hmira.read_mesh(path, repair=False)


def test_pig_stl_python_and_cli_tell_the_same_story(data, cli, tmp_path):
    path = data / "meshes" / "pig.stl"
    with pytest.warns(hmira.RepairWarning):
        m = hmira.read_mesh(path)
    r = subprocess.run([cli, "smooth", str(path), str(tmp_path / "o.off"), "--iterations", "1"], capture_output=True,
                       text=True)
    assert m.repairs in r.stderr + r.stdout


def test_from_trimesh_refuses_what_the_docstring_refuses():
    fin = types.SimpleNamespace(vertices=np.array(FIN_V, float), faces=np.array(FIN_F))
    with pytest.raises(ValueError, match="Mesh"):
        hmira.Mesh.from_trimesh(fin)
    repaired = hmira.Mesh.from_trimesh(fin, repair=True)
    assert repaired.face_count == 3 and repaired.repairs and repaired.validate() == []
    # two tetrahedra sharing one vertex: every edge is fine, the vertex is pinched
    tet_v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]]
    tet_f = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]]
    pinch = types.SimpleNamespace(vertices=np.array(tet_v, float), faces=np.array(tet_f))
    with pytest.raises(ValueError, match="vertex 0|non-manifold|fan"):
        hmira.Mesh.from_trimesh(pinch)
    split = hmira.Mesh.from_trimesh(pinch, repair=True)
    assert split.vertex_count == 8 and split.validate() == [] and "split" in split.repairs
    good = types.SimpleNamespace(vertices=np.array(CUBE_V, float), faces=np.array([[0, 1, 2], [0, 2, 3]]))
    assert hmira.Mesh.from_trimesh(good).face_count == 2
    # two faces running an edge the same way: inconsistently oriented
    flipped = types.SimpleNamespace(vertices=np.array(CUBE_V, float), faces=np.array([[0, 1, 2], [0, 1, 3]]))
    with pytest.raises(ValueError):
        hmira.Mesh.from_trimesh(flipped)


# --- geometry basics --------------------------------------------------------------------------


def test_bounds_area_and_volume_of_a_box():
    m = box((2.0, 3.0, 5.0), (1.0, -1.0, 0.5))
    assert np.array_equal(m.bounds(), [[1, -1, 0.5], [3, 2, 5.5]])
    assert m.area() == pytest.approx(2 * (6 + 10 + 15), rel=1e-14)
    assert m.volume() == pytest.approx(30.0, rel=1e-14)
    assert len(m) == 6 == m.face_count
    m.flip()
    assert m.volume() == pytest.approx(-30.0, rel=1e-14)
    assert hmira.Mesh().bounds().shape == (0, 3)


def test_volume_and_area_of_a_sphere_approach_the_analytic_values():
    n, r = 96, 0.8
    v, f = hmira.marching_cubes(ball(n, r), 0.0, spacing=(2 / (n - 1),) * 3, origin=(-1, -1, -1))
    m = hmira.Mesh(v, f)
    assert m.volume() == pytest.approx(4 / 3 * np.pi * r**3, rel=5e-3)
    assert m.area() == pytest.approx(4 * np.pi * r**2, rel=5e-3)
    # the divergence theorem's value equals the tetrahedra sum computed with numpy
    assert m.volume() == pytest.approx(signed_volume(v, f.astype(np.int64)), rel=1e-12)


def test_face_normals_and_areas_against_numpy_cross_products():
    v, f = hmira.marching_cubes(ball(20), 0.0)
    m = hmira.Mesh(v, f)
    a, b, c = (v[f[:, i]] for i in range(3))
    cross = np.cross(b - a, c - a)
    length = np.linalg.norm(cross, axis=1)
    assert np.allclose(m.face_areas(), length / 2, rtol=1e-12, atol=0)
    assert np.allclose(m.face_normals(), cross / length[:, None], rtol=0, atol=1e-12)
    assert m.area() == pytest.approx(float((length / 2).sum()), rel=1e-12)


def test_volume_does_not_depend_on_where_a_closed_mesh_is():
    v, f = hmira.marching_cubes(ball(20), 0.0)
    m = hmira.Mesh(v, f)
    assert m.translate((10.0, -7.0, 3.0)).volume() == pytest.approx(m.volume(), rel=1e-9)


def test_edges_are_the_unique_sorted_pairs_of_the_faces():
    m = box()
    e = m.edges()
    assert e.dtype == np.int32 and e.shape == (12, 2) and np.all(e[:, 0] < e[:, 1])
    expected = {tuple(sorted((f[i], f[(i + 1) % len(f)]))) for f in CUBE_F for i in range(len(f))}
    assert {tuple(map(int, x)) for x in e} == expected
    assert len(e) == m.topology().edges


def test_split_gives_each_component():
    a, b = box(), box((2.0, 2.0, 2.0), (5.0, 0.0, 0.0))
    va, fa = np.asarray(a.vertices), np.asarray(a.faces)
    vb, fb = np.asarray(b.vertices), np.asarray(b.faces)
    both = hmira.Mesh(np.vstack([vb, va]), np.vstack([fb, fa + 8]))  # the big one first
    parts = both.split()
    assert [p.face_count for p in parts] == [6, 6]
    assert [p.volume() for p in parts] == pytest.approx([8.0, 1.0])
    assert all(p.validate() == [] for p in parts)
    assert np.array_equal(np.asarray(parts[1].vertices), va)


def test_apply_transform_matches_numpy():
    rng = np.random.default_rng(1)
    m = box((1.0, 2.0, 3.0))
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    t = np.eye(4)
    t[:3, :3] = q * 1.5
    t[:3, 3] = [1, 2, 3]
    out = m.apply_transform(t)
    v = np.asarray(m.vertices)
    assert np.allclose(np.asarray(out.vertices), v @ t[:3, :3].T + t[:3, 3], rtol=0, atol=1e-12)
    # a mirror keeps the solid outward: positive volume, scaled by |det|
    assert out.volume() == pytest.approx(6.0 * abs(np.linalg.det(t[:3, :3])), rel=1e-12)
    assert np.array_equal(np.asarray(m.vertices), v)  # the original is untouched
    assert m.scale(2.0).volume() == pytest.approx(48.0)
    assert np.array_equal(m.scale(2.0, center=(1, 1, 1)).bounds(), [[-1, -1, -1], [1, 3, 5]])
    assert np.array_equal(m.translate((1, 0, 0)).bounds(), [[1, 0, 0], [2, 2, 3]])
    with pytest.raises(ValueError, match="last row"):
        m.apply_transform(np.ones((4, 4)))
    with pytest.raises(ValueError, match="4x4"):
        m.apply_transform(np.eye(3))


def test_pickle_round_trip_is_equal():
    v, f = hmira.marching_cubes(ball(16), 0.0)
    m = hmira.Mesh(v, f)
    m.vertex_colors = np.tile(np.array([10, 20, 30], np.uint8), (m.vertex_count, 1))
    back = pickle.loads(pickle.dumps(m))
    assert type(back) is hmira.Mesh
    assert np.array_equal(np.asarray(back.vertices), np.asarray(m.vertices))
    assert np.array_equal(back.faces, m.faces)
    assert np.array_equal(back.vertex_colors, m.vertex_colors)
    poly = box()
    assert pickle.loads(pickle.dumps(poly)).polygons == poly.polygons
    assert pickle.loads(pickle.dumps(poly)).vertex_colors is None


def test_vertex_colors_round_trip_through_ply(tmp_path):
    m = box()
    assert m.vertex_colors is None
    rgba = np.arange(32, dtype=np.uint8).reshape(8, 4)
    m.vertex_colors = rgba
    assert np.array_equal(m.vertex_colors, rgba)
    m.write(str(tmp_path / "c.ply"), ascii=True)
    back = hmira.read_mesh(tmp_path / "c.ply")
    assert np.array_equal(back.vertex_colors[:, :3], rgba[:, :3])
    with pytest.raises(ValueError):
        m.vertex_colors = np.zeros((3, 3), np.uint8)
    m.vertex_colors = None
    assert m.vertex_colors is None


# --- volumes ----------------------------------------------------------------------------------


def test_read_volume_raw_by_arguments_and_by_sidecar(tmp_path):
    samples = np.arange(2 * 3 * 4, dtype=np.int16).reshape((2, 3, 4), order="F")
    path = tmp_path / "v.raw"
    samples.ravel(order="F").tofile(path)
    vol, spacing, origin = hmira.read_volume(path, dims=(2, 3, 4), dtype="int16", spacing=0.5)
    assert vol.dtype == np.int16 and np.array_equal(vol, samples)
    assert spacing == (0.5, 0.5, 0.5) and origin == (0.0, 0.0, 0.0)
    (tmp_path / "v.raw.txt").write_text("# grid\nfile: v.raw\ndims: 2,3,4\ntype: int16\nspacing: 1,2,3\n"
                                        "origin: 4,5,6  # centre of voxel (0, 0, 0)\n")
    vol, spacing, origin = hmira.read_volume(path)
    assert np.array_equal(vol, samples) and spacing == (1, 2, 3) and origin == (4, 5, 6)
    with pytest.raises(ValueError, match="dims"):
        hmira.read_volume(tmp_path / "missing-sidecar.raw")
    with pytest.raises(ValueError, match="truncated"):
        hmira.read_volume(path, dims=(20, 3, 4), dtype="int16")


def test_read_volume_inr_matches_an_independent_reader(data):
    for name in ("liver.inr.gz", "skull_2.9.inr"):
        path = data / "images" / name
        vol, spacing, origin = hmira.read_volume(path)
        ref, ref_spacing = read_inr(path)
        assert vol.shape == ref.shape and np.array_equal(vol, ref.astype(np.float32))
        assert spacing == pytest.approx(ref_spacing)


def test_voxelize_raw_reads_back_and_meshes(cli, tmp_path, data):
    out = tmp_path / "bunny.raw"
    run_cli(cli, "voxelize", data / "meshes" / "bunny00.off", out, "--resolution", "24")
    vol, spacing, origin = hmira.read_volume(out)
    v, f = hmira.marching_cubes(vol, spacing=spacing, origin=origin, inside="above")  # default iso 0.5
    run_cli(cli, "mc", out, tmp_path / "cli.off", "--dims", ",".join(map(str, vol.shape)), "--type", "uint8",
            "--spacing", ",".join(map(repr, spacing)), "--origin", ",".join(map(repr, origin)), "--inside", "above")
    c = hmira.read_mesh(tmp_path / "cli.off")
    assert c.face_count == len(f) and hmira.Mesh(v, f).volume() > 0


def test_cli_mc_refuses_an_iso_outside_the_range(cli, tmp_path):
    path = tmp_path / "v.raw"
    (ball(8) < 0).astype(np.uint8).ravel(order="F").tofile(path)
    r = subprocess.run([cli, "mc", str(path), str(tmp_path / "o.off"), "--dims", "8,8,8", "--type", "uint8",
                        "--iso", "5"], capture_output=True, text=True)
    assert r.returncode != 0 and "range [0, 1]" in r.stderr


# --- one vocabulary ---------------------------------------------------------------------------


def open_fan(n):
    """One n-gon: a boundary loop of n edges."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return hmira.Mesh(np.c_[np.cos(t), np.sin(t), np.zeros(n)], [list(range(n))])


def test_fill_holes_defaults_to_the_clis_max_edges(cli, tmp_path):
    small, big = open_fan(1000), open_fan(1001)
    assert small.fill_holes()["filled"] == 1
    assert big.fill_holes()["filled"] == 0
    path = tmp_path / "big.off"
    open_fan(1001).write(str(path))
    run_cli(cli, "fill-holes", path, tmp_path / "out.off")
    assert hmira.read_mesh(tmp_path / "out.off").face_count == 1  # the CLI's default leaves it open too


def test_fill_holes_default_without_cli():
    assert open_fan(1000).fill_holes()["filled"] == 1
    r = open_fan(1001).fill_holes()
    assert r["filled"] == 0 and "max_edges 1000" in r["open"][0]["reason"]
    with pytest.warns(DeprecationWarning, match="max_size"):
        assert open_fan(12).fill_holes(max_size=12)["filled"] == 1


def test_decimate_old_names_are_deprecated_aliases():
    v, f = hmira.marching_cubes(ball(20), 0.0)
    a, b = hmira.Mesh(v, f), hmira.Mesh(v, f)
    ra = a.decimate(target_ratio=0.3, fix_boundary=True, fixed_vertices=[0, 5])
    with pytest.warns(DeprecationWarning, match="fixed_vertices"):
        rb = b.decimate(target_ratio=0.3, keep_boundary=True, locked_vertices=[0, 5])
    assert ra == rb and np.array_equal(np.asarray(a.vertices), np.asarray(b.vertices))


def test_render_honours_or_refuses_the_extension(tmp_path):
    m = box()
    with pytest.raises(ValueError, match=r"\.gif"):
        hmira.render(m, tmp_path / "x.gif")
    from hmira import viewer

    png = b"\x89PNG\r\n\x1a\n"
    try:
        from PIL import Image
    except ImportError:
        with pytest.raises(ValueError, match="Pillow"):
            viewer._encoder_for("x.jpg")
        return
    import io

    buf = io.BytesIO()
    Image.new("RGBA", (4, 4), (255, 0, 0, 255)).save(buf, format="PNG")
    png = buf.getvalue()
    jpg = viewer._encoder_for(tmp_path / "x.jpg")(png)
    assert jpg[:3] == b"\xff\xd8\xff"
    assert viewer._encoder_for("x.webp")(png)[8:12] == b"WEBP"
    assert viewer._encoder_for("x.PNG")(png) == png


def test_render_writes_a_real_jpeg(tmp_path):
    from hmira import viewer

    if viewer.find_chromium() is None:
        pytest.skip("no Chromium")
    try:
        hmira.render(box(), tmp_path / "x.jpg", size=(64, 48))
    except RuntimeError as e:
        pytest.skip(f"render unavailable here: {e}")
    assert (tmp_path / "x.jpg").read_bytes()[:3] == b"\xff\xd8\xff"


def test_names_in_the_signatures():
    sig = hmira._core.MeshCore.decimate.__doc__
    assert "fix_boundary" in sig and "fixed_vertices" in sig and "keep_boundary: bool" not in sig
    assert "max_edges: int = 1000" in hmira._core.MeshCore.fill_holes.__doc__
