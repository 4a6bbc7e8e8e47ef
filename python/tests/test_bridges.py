"""Mesh.from_/to_open3d, pyvista and meshio: a round trip keeps positions, faces and colours,
each package's own view of the result agrees (counts, areas), and a non-manifold input is refused
as Mesh(V, F) refuses it. Importing hmira never imports them; each test skips without its package."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import hmira

CUBE_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
CUBE_Q = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
# A quad, a triangle and a pentagon sharing edges: faces of three sizes.
MIXED_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0.5, 0], [-1, 0, 0], [-1, 1, 0], [-0.5, 1.5, 0]],
                   float)
MIXED_F = [[0, 1, 2, 3], [1, 4, 2], [0, 3, 7, 6, 5]]
FIN_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
FIN_F = [[0, 1, 2], [1, 0, 3], [0, 1, 4]]


def cube():
    m = hmira.Mesh(CUBE_V, CUBE_Q)
    m.vertex_colors = np.arange(32, dtype=np.uint8).reshape(8, 4) * 7
    return m


def test_importing_hmira_imports_none_of_the_bridged_packages():
    code = "import sys, hmira; print(sorted(m for m in ('open3d', 'pyvista', 'meshio', 'vtk') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_open3d_round_trip_keeps_triangles_and_colours():
    o3d = pytest.importorskip("open3d")
    m = cube()
    t = m.to_open3d()
    assert isinstance(t, o3d.geometry.TriangleMesh)
    assert len(t.triangles) == 12 and len(t.vertices) == 8  # the quads triangulated in the copy
    assert m.face_count == 6  # the mesh itself keeps its quads
    assert t.get_surface_area() == pytest.approx(m.area()) and t.is_watertight()
    np.testing.assert_allclose(np.asarray(t.vertex_colors), m.vertex_colors[:, :3] / 255.0)
    back = hmira.Mesh.from_open3d(t)
    np.testing.assert_array_equal(np.asarray(back.vertices), CUBE_V)
    assert back.polygons == np.asarray(t.triangles).tolist()
    np.testing.assert_array_equal(back.vertex_colors[:, :3], m.vertex_colors[:, :3])
    assert back.volume() == pytest.approx(1.0)


def test_open3d_non_manifold_is_refused_unless_repaired():
    o3d = pytest.importorskip("open3d")
    fin = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(np.array(FIN_V, float)),
                                    o3d.utility.Vector3iVector(np.array(FIN_F, np.int32)))
    with pytest.raises(ValueError, match="^Mesh: "):
        hmira.Mesh.from_open3d(fin)
    with pytest.warns(hmira.RepairWarning):
        assert hmira.Mesh.from_open3d(fin, repair=True).validate() == []


def test_pyvista_round_trip_keeps_polygons_of_every_size():
    pv = pytest.importorskip("pyvista")
    m = hmira.Mesh(MIXED_V, MIXED_F)
    p = m.to_pyvista()
    assert isinstance(p, pv.PolyData) and p.n_cells == 3 and p.n_points == 8
    assert p.area == pytest.approx(m.area())
    back = hmira.Mesh.from_pyvista(p)
    assert back.polygons == MIXED_F
    np.testing.assert_array_equal(np.asarray(back.vertices), MIXED_V)
    c = cube()
    pc = c.to_pyvista()
    np.testing.assert_array_equal(pc.point_data["RGBA"], c.vertex_colors)
    assert pc.volume == pytest.approx(1.0)
    np.testing.assert_array_equal(hmira.Mesh.from_pyvista(pc).vertex_colors, c.vertex_colors)


def test_pyvista_built_sphere_converts_and_is_refused_when_non_manifold():
    pv = pytest.importorskip("pyvista")
    s = pv.Sphere(theta_resolution=12, phi_resolution=8).clean()
    m = hmira.Mesh.from_pyvista(s)
    assert (m.vertex_count, m.face_count) == (s.n_points, s.n_cells)
    assert m.area() == pytest.approx(s.area) and m.volume() == pytest.approx(s.volume)
    fin = pv.PolyData(np.array(FIN_V, float), np.hstack([[3, *f] for f in FIN_F]))
    with pytest.raises(ValueError, match="^Mesh: "):
        hmira.Mesh.from_pyvista(fin)


def test_meshio_round_trip_groups_faces_by_size():
    meshio = pytest.importorskip("meshio")
    m = hmira.Mesh(MIXED_V, MIXED_F)
    out = m.to_meshio()
    assert isinstance(out, meshio.Mesh)
    assert [(c.type, c.data.tolist()) for c in out.cells] == [("triangle", [MIXED_F[1]]), ("quad", [MIXED_F[0]]),
                                                             ("polygon", [MIXED_F[2]])]
    back = hmira.Mesh.from_meshio(out)
    assert sorted(map(tuple, back.polygons)) == sorted(map(tuple, MIXED_F))
    assert back.area() == pytest.approx(m.area())


def test_meshio_leaves_out_other_cells_and_refuses_no_surface(tmp_path):
    meshio = pytest.importorskip("meshio")
    cells = [("line", np.array([[0, 1]])), ("quad", np.array(CUBE_Q))]
    back = hmira.Mesh.from_meshio(meshio.Mesh(CUBE_V, cells))
    assert back.polygons == CUBE_Q and back.volume() == pytest.approx(1.0)
    # through a file meshio writes and reads itself: an independent route for the arrays
    path = tmp_path / "cube.vtu"
    cube().to_meshio().write(path)
    again = hmira.Mesh.from_meshio(meshio.read(path))
    assert again.polygons == CUBE_Q
    with pytest.raises(ValueError, match="no triangle, quad or polygon cells"):
        hmira.Mesh.from_meshio(meshio.Mesh(CUBE_V, [("tetra", np.array([[0, 1, 3, 4]]))]))
    with pytest.raises(ValueError, match="^Mesh: "):
        hmira.Mesh.from_meshio(meshio.Mesh(np.array(FIN_V, float), [("triangle", np.array(FIN_F))]))


def test_bridges_refuse_objects_of_the_wrong_kind():
    with pytest.raises(ValueError, match="from_open3d: expected"):
        hmira.Mesh.from_open3d(object())
    with pytest.raises(ValueError, match="from_pyvista: expected"):
        hmira.Mesh.from_pyvista(object())
    with pytest.raises(ValueError, match="from_meshio: expected"):
        hmira.Mesh.from_meshio(object())
