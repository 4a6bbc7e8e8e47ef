"""One repair story: Mesh(V, F) refuses what a half-edge mesh cannot hold as given, naming the
element, unless repair=True, which repairs as read_mesh does and says so with the same
RepairWarning and summary; a clean array input takes the one-pass build and stays silent."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import hmira

# Three triangles on the edge (0, 1).
FIN_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
FIN_F = [[0, 1, 2], [1, 0, 3], [0, 1, 4]]
# Two tetrahedra sharing vertex 0 (a pinched vertex; every edge is fine).
PINCH_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1]]
PINCH_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]]


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for p in vertices:
            f.write(" ".join(map(str, p)) + "\n")
        for face in faces:
            f.write(f"{len(face)} " + " ".join(map(str, face)) + "\n")


@pytest.mark.parametrize("as_array", [True, False], ids=["array", "lists"])
def test_mesh_refuses_a_non_manifold_edge_naming_it(as_array):
    faces = np.array(FIN_F) if as_array else FIN_F
    with pytest.raises(ValueError, match=r"^Mesh: .*(edge|face)"):
        hmira.Mesh(FIN_V, faces)


def test_mesh_refuses_a_pinched_vertex_naming_it():
    with pytest.raises(ValueError, match=r"^Mesh: .*(vertex 0|non-manifold|fan)"):
        hmira.Mesh(PINCH_V, np.array(PINCH_F))


@pytest.mark.parametrize("v, f", [(FIN_V, FIN_F), (PINCH_V, PINCH_F)], ids=["fin", "pinch"])
def test_repair_true_gives_what_read_mesh_gives_with_the_same_warning(tmp_path, v, f):
    path = tmp_path / "m.off"
    write_off(path, v, f)
    with pytest.warns(hmira.RepairWarning) as read_warning:
        from_file = hmira.read_mesh(path)
    with pytest.warns(hmira.RepairWarning) as built_warning:
        built = hmira.Mesh(v, np.array(f), repair=True)
    assert built.repairs and built.repairs == from_file.repairs
    assert str(built_warning[0].message).endswith("repaired for editing: " + from_file.repairs)
    assert str(read_warning[0].message).endswith("repaired for editing: " + built.repairs)
    assert built.validate() == []
    assert (built.vertex_count, built.face_count) == (from_file.vertex_count, from_file.face_count)
    np.testing.assert_array_equal(np.asarray(built.vertices), np.asarray(from_file.vertices))
    assert built.polygons == from_file.polygons


def test_clean_input_is_built_silently_and_unchanged():
    v = np.array(PINCH_V[:4], float)
    f = np.array(PINCH_F[:4], dtype=np.int32)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for repair in (False, True):
            m = hmira.Mesh(v, f, repair=repair)
            assert m.repairs == "" and m.polygons == f.tolist()
            np.testing.assert_array_equal(np.asarray(m.vertices), v)


def test_from_trimesh_repair_warns_as_well():
    class Fin:
        vertices = np.array(FIN_V, float)
        faces = np.array(FIN_F)

    with pytest.warns(hmira.RepairWarning, match="repaired for editing"):
        m = hmira.Mesh.from_trimesh(Fin(), repair=True)
    assert m.repairs and m.validate() == []
