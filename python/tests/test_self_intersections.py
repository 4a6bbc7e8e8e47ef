"""Mesh.self_intersections: the exact face pairs as a (k, 2) array, checked against an
independent brute force on integer soups (separating axes in exact integer arithmetic)."""
from __future__ import annotations

import itertools

import numpy as np

import hmira


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def _dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def _triangles_meet(s, t):
    """Closed proper triangles meet: no separating axis among the face normals, the edge cross
    products and the in-plane edge normals (Python integers: exact)."""
    e = [_sub(s[(i + 1) % 3], s[i]) for i in range(3)]
    f = [_sub(t[(i + 1) % 3], t[i]) for i in range(3)]
    ns, nt = _cross(e[0], e[1]), _cross(f[0], f[1])
    axes = [ns, nt] + [_cross(ns, x) for x in e] + [_cross(nt, x) for x in f]
    axes += [_cross(x, y) for x in e for y in f]
    for ax in axes:
        if ax == [0, 0, 0]:
            continue
        ps, pt = [_dot(ax, p) for p in s], [_dot(ax, p) for p in t]
        if max(ps) < min(pt) or max(pt) < min(ps):
            return False
    return True


def test_a_soup_of_separate_triangles_matches_brute_force():
    rng = np.random.default_rng(5)
    tris = []
    while len(tris) < 40:
        t = rng.integers(0, 7, size=(3, 3)).tolist()
        if _cross(_sub(t[1], t[0]), _sub(t[2], t[0])) != [0, 0, 0]:
            tris.append(t)
    v = np.array([p for t in tris for p in t], dtype=float)
    f = np.arange(len(v)).reshape(-1, 3)
    got = hmira.Mesh(v, f).self_intersections()
    assert got.dtype == np.int64 and got.shape[1] == 2
    want = [[i, j] for i, j in itertools.combinations(range(len(tris)), 2) if _triangles_meet(tris[i], tris[j])]
    assert len(want) > 5
    assert got.tolist() == want


def test_the_tetrahedron_with_a_triangle_through_it(data):
    m = hmira.read_mesh(str(data / "meshes" / "tetra_intersected_by_triangle.off"))
    pairs = m.self_intersections()
    assert len(pairs) > 0 and (pairs[:, 1] == 4).all()


def test_a_clean_sphere_has_none(data):
    m = hmira.read_mesh(str(data / "meshes" / "sphere.off"))
    assert m.self_intersections().shape == (0, 2)
