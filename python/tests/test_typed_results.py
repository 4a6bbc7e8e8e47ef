"""The Mesh operations return typed results with the C++ report's field names: attributes, the
mapping access the old dicts offered (r["faces"], keys(), dict(r), == with a dict), a readable
repr, and stubs that name the classes instead of dict."""
from __future__ import annotations

import pathlib
import typing

import numpy as np
import pytest

import hmira

TET_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TET_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
QUAD_V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]


def tet():
    return hmira.Mesh(TET_V, TET_F)


def grid(n=6):
    x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0), indexing="ij")
    v = np.c_[x.ravel(), y.ravel(), np.zeros(x.size)]
    f = []
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j
            f += [[a, a + n + 1, a + n + 2], [a, a + n + 2, a + 1]]
    return hmira.Mesh(v, np.array(f))


CASES = {
    "subdivide": (lambda: hmira.Mesh(QUAD_V, [[0, 1, 2, 3]]), lambda m: m.subdivide(scheme="catmull-clark"),
                  hmira.SubdivideResult, ("vertices", "edges", "faces")),
    "triangulate_faces": (lambda: hmira.Mesh(QUAD_V, [[0, 1, 2, 3]]), lambda m: m.triangulate_faces(),
                          hmira.TriangulateResult, ("faces_cut", "triangles_added")),
    "decimate": (grid, lambda m: m.decimate(target_faces=40), hmira.DecimateResult,
                 ("faces", "vertices", "collapses", "triangulated", "stopped_by", "error", "note")),
    "remesh": (grid, lambda m: m.remesh(target_edge_length=0.5, iterations=1), hmira.RemeshResult,
               ("splits", "collapses", "flips", "feature_edges")),
    "fill_holes": (grid, lambda m: m.fill_holes(), hmira.FillHolesResult,
                   ("filled", "skipped", "faces_added", "vertices_added", "unfaired", "open")),
    "truncate": (tet, lambda m: m.truncate([0], fraction=0.5), hmira.TruncateResult, ("faces", "vertices")),
    "bevel": (tet, lambda m: m.bevel([(0, 1)], width=0.05), hmira.BevelResult,
              ("strip_faces", "vertex_faces", "vertices", "width")),
    "extrude": (lambda: hmira.Mesh(QUAD_V, [[0, 1, 2, 3]]), lambda m: m.extrude([0], distance=2.0),
                hmira.ExtrudeResult, ("top_faces", "side_faces", "vertices")),
}


@pytest.mark.parametrize("name", list(CASES))
def test_each_operation_returns_its_typed_result_with_the_cpp_field_names(name):
    make, run, cls, fields = CASES[name]
    r = run(make())
    assert type(r) is cls and not isinstance(r, dict)
    assert tuple(r.keys()) == fields == cls._fields
    as_dict = dict(r)
    assert list(as_dict) == list(fields) and as_dict == r._asdict()
    for f in fields:
        assert r[f] is getattr(r, f) or r[f] == getattr(r, f)
    assert r == as_dict and not (r != as_dict) and r != {**as_dict, fields[0]: "other"}
    assert repr(r).startswith(cls.__name__ + "(" + fields[0] + "=")
    with pytest.raises(KeyError):
        r["no_such_field"]
    with pytest.raises(AttributeError):
        setattr(r, fields[0], 1)


def test_values_match_an_independent_count():
    q = hmira.Mesh(QUAD_V, [[0, 1, 2, 3]])
    r = q.subdivide(scheme="catmull-clark")
    assert (r.vertices, r.edges, r.faces) == (q.vertex_count, len(q.edges()), q.face_count) == (9, 12, 4)
    m = grid()
    before = m.face_count
    d = m.decimate(target_faces=40)
    assert d.faces == m.face_count <= 40 < before and d.vertices == m.vertex_count
    assert d.collapses == (before - d.faces) // 2  # each interior collapse removes two triangles
    assert d.stopped_by in ("target_faces", "max_error", "constraints") and isinstance(d.error, float)


def test_open_holes_are_typed_too():
    m = grid()
    r = m.fill_holes(3)  # the rim (24 edges) is longer than 3: left open
    assert r.filled == 0 and r.skipped == 1 and len(r.open) == 1
    hole = r.open[0]
    assert type(hole) is hmira.OpenHole and hole.edges == 24 and "max_edges 3" in hole.reason
    assert r["open"][0]["edges"] == 24  # the old dict-style access still works


def test_stubs_name_the_result_classes_not_dict():
    stubs = (pathlib.Path(hmira.__file__).parent / "_core.pyi").read_text()
    for method, cls in [("decimate", "DecimateResult"), ("fill_holes", "FillHolesResult"), ("remesh", "RemeshResult"),
                        ("subdivide", "SubdivideResult"), ("triangulate_faces", "TriangulateResult")]:
        line = next(l for l in stubs.splitlines() if l.lstrip().startswith(f"def {method}("))
        assert line.rstrip().endswith(f"-> {cls}:"), line
    assert "def open(self) -> list[OpenHole]" in stubs
    # The Python wrappers (truncate, bevel, extrude, decimate, fill_holes) say so in their annotations.
    for method, cls in [("truncate", hmira.TruncateResult), ("bevel", hmira.BevelResult),
                        ("extrude", hmira.ExtrudeResult), ("decimate", hmira.DecimateResult),
                        ("fill_holes", hmira.FillHolesResult)]:
        assert typing.get_type_hints(getattr(hmira.Mesh, method))["return"] is cls
        assert typing.get_type_hints(getattr(hmira, method, getattr(hmira.Mesh, method)))["return"] is cls
