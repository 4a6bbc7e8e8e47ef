"""Mesh.decimate: face targets met exactly, the genus kept, boundary and locked
vertices left where they were, max_error honoured, polygons triangulated with a note, bad
options refused with the mesh unchanged, and the same result as the C++ CLI on a real mesh."""
import numpy as np
import pytest

import hmira
from conftest import canonical, run_cli


def torus(n=24, m=16, R=2.0, r=0.7, holes=False):
    """A torus of n x m quads cut into triangles; with holes, some separated quads left out."""
    u, v = np.meshgrid(np.arange(n) * 2 * np.pi / n, np.arange(m) * 2 * np.pi / m, indexing="ij")
    pts = np.stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)], -1).reshape(-1, 3)
    rng = np.random.default_rng(5)
    pts = pts + rng.uniform(-0.01, 0.01, pts.shape)
    idx = lambda i, j: (i % n) * m + (j % m)
    faces = []
    for i in range(n):
        for j in range(m):
            if holes and i % 5 == 2 and j % 4 == 1:
                continue
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            faces += [[a, b, c], [a, c, d]]
    return hmira.Mesh(pts, faces)


def boundary_points(m):
    """The positions of the vertices on a boundary edge (an edge used by one face), sorted."""
    count = {}
    for f in m.polygons:
        for a, b in zip(f, f[1:] + f[:1]):
            count[(min(a, b), max(a, b))] = count.get((min(a, b), max(a, b)), 0) + 1
    ids = sorted({v for e, k in count.items() if k == 1 for v in e})
    return sorted(map(tuple, np.array(m.vertices)[ids].tolist()))


@pytest.mark.parametrize("target", [767, 400, 97, 40])
def test_face_targets_are_met_exactly_and_the_genus_kept(target):
    m = torus()
    r = m.decimate(target_faces=target)
    assert r["stopped_by"] == "target_faces"
    assert target - 1 <= r["faces"] <= target
    t = m.topology()
    assert t.faces == r["faces"] and t.vertices == r["vertices"]
    assert t.vertices - t.edges + t.faces == 0
    assert m.validate() == []


def test_boundary_vertices_stay_and_loops_are_kept():
    m = torus(holes=True)
    before = boundary_points(m)
    loops = m.topology().boundary_loops
    assert m.topology().faces == 2 * (24 * 16 - 5 * 4)  # 20 quads left out
    r = m.decimate(target_ratio=0.2)
    assert r["stopped_by"] == "target_faces"
    assert r["faces"] == 146  # ceil(0.2 * 728), reached exactly
    assert boundary_points(m) == before
    assert m.topology().boundary_loops == loops
    assert m.validate() == []


def test_fixed_vertices_keep_their_coordinates_exactly():
    m = torus(holes=True)
    locked = list(range(0, 384, 7))
    pts = np.array(m.vertices)[locked].copy()
    m.decimate(target_ratio=0.1, fix_boundary=False, fixed_vertices=locked)
    after = {tuple(p) for p in np.array(m.vertices).tolist()}
    assert all(tuple(p) in after for p in pts.tolist())
    assert m.validate() == []


def test_a_flat_patch_stays_flat_and_max_error_is_a_distance():
    n = 8
    pts = [[i, j, 0.0] for j in range(n + 1) for i in range(n + 1)]
    faces = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            faces += [[a, b, c], [a, c, d]]
    m = hmira.Mesh(pts, faces)
    r = m.decimate(max_error=1e-9)
    assert r["error"] <= 1e-9
    assert np.all(np.array(m.vertices)[:, 2] == 0)
    assert m.topology().vertices == 4 * n  # only the outline is left
    assert m.validate() == []


def test_polygons_are_triangulated_first_with_a_note():
    v = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    m = hmira.Mesh(v, f)
    r = m.decimate(target_faces=12, max_normal_angle=180)
    assert r["triangulated"] and "triangulated" in r["note"]
    assert all(len(p) == 3 for p in m.polygons)
    assert m.validate() == []


@pytest.mark.parametrize(
    "kwargs, name",
    [({}, "target_faces, target_ratio or max_error"), ({"target_ratio": float("nan")}, "target_ratio"),
     ({"target_ratio": 2.0}, "target_ratio"), ({"max_error": -1.0}, "max_error"),
     ({"target_faces": 10, "max_normal_angle": float("nan")}, "max_normal_angle"),
     ({"target_faces": 10, "fixed_vertices": [10**6]}, "decimate")])
def test_bad_options_are_refused_by_name_and_change_nothing(kwargs, name):
    m = torus()
    before = (np.array(m.vertices).tolist(), m.polygons)
    with pytest.raises(ValueError, match=name):
        m.decimate(**kwargs)
    assert (np.array(m.vertices).tolist(), m.polygons) == before


def test_same_result_as_the_cli(cli, data, tmp_path):
    out = tmp_path / "small.off"
    run_cli(cli, "decimate", str(data / "meshes" / "bunny00.off"), str(out), "--ratio", "0.1")
    m = hmira.read_mesh(str(data / "meshes" / "bunny00.off"))
    m.decimate(target_ratio=0.1)
    c = hmira.read_mesh(str(out))
    (va, fa), (vb, fb) = canonical(np.array(m.vertices), m.polygons), canonical(np.array(c.vertices), c.polygons)
    assert fa == fb
    assert np.allclose(va, vb, atol=1e-12, rtol=1e-12)
