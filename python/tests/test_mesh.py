"""hmira.Mesh: construction (arrays, polygon lists, mesh-like objects), the checked vertices
view, topology and validation, edits with the CLI's options (compared with the CLI), Euler
operators with undo (hypothesis), I/O round trips and error handling."""
import gc
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import hmira
from conftest import canonical, run_cli

TETRA_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TETRA_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
CUBE_V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
CUBE_F = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
REAL_MESHES = ["bunny00.off", "anchor.off", "cactus.off", "3torus.off", "blobby.off"]


def tetra():
    return hmira.Mesh(TETRA_V, TETRA_F)


def cube():
    return hmira.Mesh(CUBE_V, CUBE_F)


def state(m):
    return np.array(m.vertices).tolist(), m.polygons


def test_construction_from_arrays_lists_and_mesh_likes():
    a = hmira.Mesh(np.array(CUBE_V, dtype=np.float32), np.array(CUBE_F, dtype=np.uint16))
    b = hmira.Mesh(CUBE_V, [tuple(f) for f in CUBE_F])

    class Like:
        vertices = np.array(CUBE_V)
        faces = np.array(CUBE_F)

    c = hmira.as_mesh(Like())
    for m in (a, b, c):
        assert (m.vertex_count, m.edge_count, m.face_count) == (8, 12, 6)
        np.testing.assert_array_equal(m.faces, CUBE_F)
        assert m.faces.dtype == np.int32 and m.validate() == []
    mixed = hmira.Mesh(CUBE_V[:5], [[0, 1, 2, 3], [0, 4, 1], [1, 4, 2], [2, 4, 3], [3, 4, 0]])
    assert [len(p) for p in mixed.polygons] == [4, 3, 3, 3, 3]
    with pytest.raises(ValueError, match="Mesh.polygons"):
        mixed.faces


def test_bad_construction_raises_value_error_naming_the_face():
    with pytest.raises(ValueError, match="out of range"):
        hmira.Mesh(TETRA_V, [[0, 1, 7]])
    # The same edge twice in the same direction: refused naming the edge (repair=True would flip a face).
    with pytest.raises(ValueError, match="edge 0->1 is run in the same direction by two faces"):
        hmira.Mesh(TETRA_V, [[0, 1, 2], [0, 1, 2]])
    with pytest.raises(ValueError, match="non-finite"):
        hmira.Mesh([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(ValueError):
        hmira.Mesh(TETRA_V, None)


def test_vertices_is_a_writable_view_onto_the_mesh():
    m = cube()
    v = m.vertices
    v[0] = [-1, -1, -1]
    np.testing.assert_array_equal(m.vertices[0], [-1, -1, -1])
    v += 1.0
    np.testing.assert_array_equal(m.vertices[6], [2, 2, 2])
    assert isinstance(v, hmira.VertexView) and v.shape == (8, 3)


def test_a_view_raises_after_a_topology_change_or_collection():
    m = cube()
    v = m.vertices
    row = v[1:3]
    m.truncate([0], fraction=0.25)
    for use in (lambda: v[0], lambda: v + 1, lambda: repr(v), lambda: np.sum(v), lambda: row[0], lambda: len(v)):
        with pytest.raises(RuntimeError, match="stale"):
            use()
    assert m.vertices.shape == (10, 3)  # a fresh view sees the new vertices
    w = cube().vertices
    gc.collect()
    with pytest.raises(RuntimeError, match="no longer exists"):
        w[0]
    # Even bypassing the check, the memory is the old (kept-alive) storage, never freed memory.
    assert np.asarray(w.view(np.ndarray)).shape == (8, 3)


def test_topology_and_validate_on_real_meshes_match_the_cli(data, cli):
    for name in REAL_MESHES:
        path = data / "meshes" / name
        m = hmira.read_mesh(path)
        t = m.topology()
        info = json.loads(run_cli(cli, "info", path, "--json"))
        flat = json.dumps(info)
        assert t.vertices == m.vertex_count and t.faces == m.face_count
        assert f'"genus": {t.genus}' in flat, name
        assert f'"faces": {t.faces}' in flat, name
        assert m.validate() == [], name


def test_topology_of_known_shapes():
    x, y, z = np.mgrid[-1.5:1.5:48j, -1.5:1.5:48j, -1.5:1.5:48j]
    v, f = hmira.marching_cubes(np.sqrt((np.sqrt(x**2 + y**2) - 1) ** 2 + z**2) - 0.35, 0.0)
    t = hmira.mesh_topology((v, f))
    assert (t.genus, t.components, t.boundary_loops, t.euler_characteristic) == (1, 1, 0, 0)
    open_cube = hmira.Mesh(CUBE_V, CUBE_F[1:])
    assert open_cube.topology().boundary_loops == 1


def test_flip_reverses_winding_and_normals():
    m = cube()
    n0 = m.vertex_normals()
    assert hmira.flip_normals(m) == 6
    np.testing.assert_allclose(m.vertex_normals(), -n0, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(n0, axis=1), 1.0)
    np.testing.assert_allclose(n0[6], np.ones(3) / np.sqrt(3), atol=1e-12)
    assert m.validate() == []


@pytest.mark.parametrize("edit", [
    ("truncate", dict(all=True, fraction=0.3), ["truncate", "--all", "--fraction", "0.3"]),
    ("truncate", dict(vertices=[0, 5], distance=0.2), ["truncate", "--vertex", "0,5", "--distance", "0.2"]),
    ("bevel", dict(all=True, width=0.1, segments=2), ["bevel", "--all", "--width", "0.1", "--segments", "2"]),
    ("bevel", dict(edges=[(0, 1)], width=0.2), ["bevel", "--edge", "0,1", "--width", "0.2"]),
    ("extrude", dict(faces=[1], distance=0.5), ["extrude", "--face", "1", "--distance", "0.5"]),
    ("extrude", dict(all=True, distance=0.25, mode="individual"), ["extrude", "--all", "--distance", "0.25", "--mode", "individual"]),
])
def test_edits_match_the_cli(cli, tmp_path, edit):
    method, options, args = edit
    src = tmp_path / "cube.off"
    hmira.write_mesh(src, cube())
    m = hmira.read_mesh(src)
    summary = getattr(m, method)(**options)
    assert summary["vertices"] > 0 and m.validate() == []
    out = tmp_path / "out.off"
    run_cli(cli, args[0], src, out, *args[1:], "-q")
    c = hmira.read_mesh(out)
    pv, pf = canonical(np.array(m.vertices), m.polygons)
    cv, cf = canonical(np.array(c.vertices), c.polygons)
    np.testing.assert_allclose(pv, cv, atol=1e-12)
    assert pf == cf


def test_edits_on_real_meshes_keep_them_valid(data):
    m = hmira.read_mesh(data / "meshes" / "bunny00.off")
    chi = m.topology().euler_characteristic
    m.truncate([0, 10, 20], fraction=0.25)
    assert m.validate() == [] and m.topology().euler_characteristic == chi
    m.extrude([5, 6, 7], distance=0.01, mode="individual")
    assert m.validate() == [] and m.topology().euler_characteristic == chi


def test_failed_edits_leave_the_mesh_and_arguments_unchanged():
    m = cube()
    before = state(m)
    faces = [0, 99]
    with pytest.raises(ValueError, match="face 99"):
        m.extrude(faces)
    with pytest.raises(ValueError, match="fraction"):
        m.truncate([0], fraction=1.5)
    with pytest.raises(ValueError, match="width"):
        m.bevel(all=True, width=-1)
    with pytest.raises(ValueError, match="no edge"):
        m.bevel([(0, 6)])
    with pytest.raises(ValueError, match="one of them"):
        m.truncate()
    assert state(m) == before and faces == [0, 99] and m.validate() == []
    # A boundary edge bevels (the strip lies in its one face): one face, two vertices, three
    # edges more for one segment, and the mesh stays valid.
    open_cube = hmira.Mesh(CUBE_V, CUBE_F[1:])
    t = open_cube.topology()
    open_cube.bevel([(0, 1)], width=0.1)
    u = open_cube.topology()
    assert (u.vertices - t.vertices, u.edges - t.edges, u.faces - t.faces) == (2, 3, 1)
    assert open_cube.validate() == [] and u.boundary_loops == 1


def test_copy_is_independent():
    m = cube()
    c = m.copy()
    c.extrude([0], distance=1.0)
    assert m.face_count == 6 and c.face_count == 10


@settings(max_examples=40, deadline=None)
@given(face=st.integers(0, 5), distance=st.floats(0.05, 2.0), individual=st.booleans())
def test_extrude_keeps_the_mesh_closed_and_valid(face, distance, individual):
    m = cube()
    m.extrude([face], distance=distance, mode="individual" if individual else "region")
    t = m.topology()
    assert m.validate() == [] and t.closed and t.genus == 0 and m.face_count == 10


@settings(max_examples=40, deadline=None)
@given(a=st.integers(0, 7), b=st.integers(0, 7), x=st.floats(-5, 5), y=st.floats(-5, 5), z=st.floats(-5, 5))
def test_euler_make_then_kill_restores_the_mesh(a, b, x, y, z):
    m = cube()
    before = state(m)
    h = m.find_halfedge(a, b)
    if h < 0:
        return
    v, e = m.make_edge_vertex(h, [x, y, z])
    assert v == 8 and m.validate(relaxed=True) == []
    m.kill_edge_vertex(e)
    m.collect_garbage()
    assert state(m) == before
    # makeEF across a face, then killEF, is the identity too.
    h2 = m.find_halfedge(0, 1)  # corners of face [0, 1, 5, 4]: a new edge from 1 to 4 splits it
    h3 = m.find_halfedge(5, 4)
    he, f = m.make_edge_face(h2, h3)
    assert m.face_count == 7 and m.validate() == []
    m.kill_edge_face(he)
    m.collect_garbage()
    assert sorted(map(sorted, m.polygons)) == sorted(map(sorted, before[1]))


@settings(max_examples=30, deadline=None)
@given(fmt=st.sampled_from(["obj", "off", "ply", "stl"]), ascii=st.booleans(), big=st.booleans(),
       scale=st.floats(1e-3, 1e3))
def test_write_read_round_trip(tmp_path_factory, fmt, ascii, big, scale):
    path = tmp_path_factory.mktemp("rt") / f"m.{fmt}"
    v = np.array(TETRA_V, dtype=float) * scale
    hmira.write_mesh(path, (v, TETRA_F), ascii=ascii, big_endian=big)
    m = hmira.read_mesh(path)
    pv, pf = canonical(np.array(m.vertices), m.polygons)
    ev, ef = canonical(v, TETRA_F)
    assert pf == ef
    np.testing.assert_allclose(pv, ev, rtol=1e-6 if fmt == "stl" else 1e-12)


def test_real_meshes_round_trip_through_every_format(data, tmp_path):
    m = hmira.read_mesh(data / "meshes" / "bunny00.off")
    ref = canonical(np.array(m.vertices), m.polygons)
    for fmt in ("obj", "off", "ply"):
        hmira.write_mesh(tmp_path / f"b.{fmt}", m)
        back = hmira.read_mesh(tmp_path / f"b.{fmt}")
        got = canonical(np.array(back.vertices), back.polygons)
        assert got[1] == ref[1]
        np.testing.assert_allclose(got[0], ref[0], rtol=1e-15)


def test_io_errors(tmp_path):
    with pytest.raises(OSError, match="missing.off"):
        hmira.read_mesh(tmp_path / "missing.off")
    (tmp_path / "bad.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(ValueError, match="bad.off"):
        hmira.read_mesh(tmp_path / "bad.off")
    with pytest.raises(ValueError, match="unknown mesh format"):
        hmira.read_mesh(tmp_path / "x.xyz")
    with pytest.raises(OSError):
        hmira.write_mesh(tmp_path / "no" / "dir" / "m.off", cube())
    target = tmp_path / "keep.off"
    target.write_text("old")
    with pytest.raises(ValueError):
        hmira.write_mesh(target, (TETRA_V, [[0, 1, 9]]))
    assert target.read_text() == "old"


def test_trimesh_interop():
    trimesh = pytest.importorskip("trimesh")
    tm = trimesh.creation.icosphere(subdivisions=2)
    m = hmira.Mesh.from_trimesh(tm)
    assert m.topology().genus == 0 and m.face_count == len(tm.faces)
    back = m.to_trimesh()
    np.testing.assert_array_equal(back.faces, tm.faces)
    assert back.volume == pytest.approx(tm.volume)
    grid, _, pitch = hmira.voxelize(tm, resolution=32)
    assert grid.sum() * pitch**3 == pytest.approx(tm.volume, rel=0.4)
