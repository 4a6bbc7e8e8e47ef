"""Faces given as Python lists: a corner of the wrong type is a TypeError, an index out of range a
ValueError, each naming the face; never a RuntimeError from inside the binding. Well-formed
lists, numpy integer scalars and integer arrays keep working."""
from __future__ import annotations

import numpy as np
import pytest

import hmira

V = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
GOOD = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]


@pytest.mark.parametrize(
    "bad",
    [None, "1", 1.0, 2.5, [1], (1,), b"\x01", True, object(), np.float64(1.0), 1j],
    ids=["None", "str", "float", "float_fraction", "nested_list", "nested_tuple", "bytes", "bool", "object",
         "numpy_float", "complex"],
)
@pytest.mark.parametrize("face", [0, 2])
def test_a_corner_of_the_wrong_type_is_a_type_error_naming_the_face(bad, face):
    faces = [list(f) for f in GOOD]
    faces[face][2] = bad
    with pytest.raises(TypeError, match=rf"^Mesh: face {face}: corner 2 is a "):
        hmira.Mesh(V, faces)


@pytest.mark.parametrize("bad", [2**70, -(2**70), 2**63, 2**64, -1, 4, 2**32, np.int64(-5), np.uint64(2**63)],
                         ids=["2**70", "-2**70", "2**63", "2**64", "-1", "4", "2**32", "numpy_negative", "numpy_uint64_big"])
@pytest.mark.parametrize("face", [0, 3])
def test_an_index_out_of_range_is_a_value_error_naming_the_face(bad, face):
    faces = [list(f) for f in GOOD]
    faces[face][1] = bad
    with pytest.raises(ValueError, match=rf"^Mesh: face {face} uses vertex -?\d+, out of range \[0, 4\)"):
        hmira.Mesh(V, faces)


@pytest.mark.parametrize("bad", [None, 3, 2.0, "012"], ids=["None", "int", "float", "str"])
def test_a_face_that_is_not_a_sequence_of_indices_is_a_type_error(bad):
    faces = [list(f) for f in GOOD]
    faces[1] = bad
    with pytest.raises(TypeError, match=r"^Mesh: face 1"):
        hmira.Mesh(V, faces)


def test_the_same_checks_apply_to_write_polygons(tmp_path):
    with pytest.raises(TypeError, match=r"^write_mesh: face 0: corner 2 is a NoneType"):
        hmira.write_mesh(tmp_path / "x.off", (V, [[0, 2, None]]))
    assert not (tmp_path / "x.off").exists()


@pytest.mark.parametrize(
    "faces",
    [
        GOOD,
        [tuple(f) for f in GOOD],
        [[np.int64(i) for i in f] for f in GOOD],
        [[np.int32(i) for i in f] for f in GOOD],
        [[np.uint8(i) for i in f] for f in GOOD],
        [np.array(f) for f in GOOD],
        np.array(GOOD, dtype=np.int32),
        np.array(GOOD, dtype=np.int64),
        np.array(GOOD, dtype=np.uint16),
    ],
    ids=["lists", "tuples", "numpy_int64", "numpy_int32", "numpy_uint8", "row_arrays", "int32_array", "int64_array",
         "uint16_array"],
)
def test_integer_faces_of_every_kind_still_build_the_mesh(faces):
    m = hmira.Mesh(V, faces)
    assert m.validate() == []
    assert m.polygons == GOOD
    np.testing.assert_array_equal(m.vertices, V)
