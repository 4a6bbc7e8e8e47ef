"""glTF 2.0 (.glb, .gltf) through read_mesh / write_mesh: a round trip keeps positions (float)
and triangles, trimesh reads what hmira writes and hmira reads what trimesh writes (an
independent implementation), colours survive, and hostile files give one-line errors."""
from __future__ import annotations

import json
import struct

import numpy as np
import pytest

import hmira

CUBE_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
CUBE_Q = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def sphere():
    x, y, z = np.mgrid[-1:1:24j, -1:1:24j, -1:1:24j]
    v, f = hmira.marching_cubes(np.sqrt(x**2 + y**2 + z**2) - 0.7, 0.0)
    return hmira.Mesh(v.astype(np.float32).astype(np.float64), f)


@pytest.mark.parametrize("ext", ["glb", "gltf"])
def test_round_trip_keeps_positions_and_triangles(tmp_path, ext):
    m = sphere()
    path = tmp_path / f"s.{ext}"
    hmira.write_mesh(path, m)
    back = hmira.read_mesh(path)
    np.testing.assert_array_equal(np.asarray(back.vertices), np.asarray(m.vertices))
    np.testing.assert_array_equal(back.faces, m.faces)
    assert back.volume() == pytest.approx(m.volume())


def test_quads_are_written_as_triangles_that_enclose_the_same_volume(tmp_path):
    cube = hmira.Mesh(CUBE_V, CUBE_Q)
    hmira.write_mesh(tmp_path / "c.glb", cube)
    back = hmira.read_mesh(tmp_path / "c.glb")
    assert (back.vertex_count, back.face_count) == (8, 12)
    assert back.volume() == pytest.approx(1.0) and back.topology().closed


def test_colours_survive_a_round_trip(tmp_path):
    cube = hmira.Mesh(CUBE_V, CUBE_Q)
    cube.vertex_colors = (np.arange(32).reshape(8, 4) * 8).astype(np.uint8)
    hmira.write_mesh(tmp_path / "c.gltf", cube)
    np.testing.assert_array_equal(hmira.read_mesh(tmp_path / "c.gltf").vertex_colors, cube.vertex_colors)


def test_trimesh_agrees_in_both_directions(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    m = sphere()
    hmira.write_mesh(tmp_path / "h.glb", m)
    t = trimesh.load(tmp_path / "h.glb", process=False, force="mesh")
    np.testing.assert_array_equal(np.asarray(t.vertices), np.asarray(m.vertices))
    np.testing.assert_array_equal(np.asarray(t.faces), m.faces)
    box = trimesh.creation.box(extents=(1, 2, 3))
    box.apply_translation((5, 0, 0))
    box.export(tmp_path / "t.glb")
    back = hmira.read_mesh(tmp_path / "t.glb")
    assert back.volume() == pytest.approx(6.0) and back.face_count == len(box.faces)
    np.testing.assert_allclose(back.bounds(), box.bounds)


def glb(doc, bin_=b""):
    j = json.dumps(doc).encode()
    j += b" " * (-len(j) % 4)
    body = struct.pack("<II", len(j), 0x4E4F534A) + j
    if bin_:
        bin_ += b"\0" * (-len(bin_) % 4)
        body += struct.pack("<II", len(bin_), 0x004E4942) + bin_
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def test_hostile_files_give_one_line_errors_naming_the_place(tmp_path):
    doc = {"asset": {"version": "2.0"},
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                         {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
           "buffers": [{"byteLength": 48}]}
    data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3I", 0, 1, 9)
    cases = {
        "index.glb": (glb(doc, data), r"index 2 is 9, out of range \[0, 3\)"),
        "trunc.glb": (glb(doc, data)[:40], "GLB header says"),
        "json.gltf": (b'{"asset": {"version": "2.0"}, "meshes": [', "byte offset"),
    }
    for name, (content, message) in cases.items():
        path = tmp_path / name
        path.write_bytes(content)
        with pytest.raises(ValueError, match=message) as e:
            hmira.read_mesh(path)
        assert "\n" not in str(e.value) and str(path) in str(e.value)
