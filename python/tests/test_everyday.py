"""The everyday operations on hmira.Mesh: flip/split/collapse with their checks,
face triangulation, hole filling, subdivision and smoothing. Each is checked against counts
worked out here, validated after every change, shown to leave the mesh unchanged when it
refuses, and (where the CLI has the command) compared with the C++ CLI on real meshes."""
import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import hmira
from conftest import canonical, run_cli, signed_volume

TETRA_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TETRA_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def sphere(n=12):
    x, y, z = np.mgrid[-1.5:1.5:n * 1j, -1.5:1.5:n * 1j, -1.5:1.5:n * 1j]
    v, f = hmira.marching_cubes(np.sqrt(x**2 + y**2 + z**2) - 1.0, 0.0, spacing=(3 / (n - 1),) * 3, origin=(-1.5,) * 3)
    return hmira.Mesh(v, f)


def cube():
    v = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return hmira.Mesh(v, f)


def state(m):
    """Everything a refused operation must leave alone: positions and faces, in order."""
    return np.array(m.vertices).tolist(), m.polygons


def same_mesh(a, b):
    """Equal after canonical relabelling: vertices sorted, faces renumbered and sorted."""
    (va, fa), (vb, fb) = canonical(*a), canonical(*b)
    return np.array_equal(va, vb) and fa == fb


def counts(m):
    t = m.topology()
    return t.vertices, t.edges, t.faces


def halfedge_between(m, a, b):
    h = m.find_halfedge(a, b)
    assert h >= 0
    return h


SPHERE = sphere()
EDGES = [(int(a), int(b)) for f in SPHERE.faces for a, b in zip(f, np.roll(f, -1))]


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(EDGES))
def test_flip_twice_restores_the_connectivity(edge):
    m = SPHERE.copy()
    before = state(m)
    h = halfedge_between(m, *edge)
    if not m.is_flip_ok(h):
        with pytest.raises(ValueError, match="flip_edge"):
            m.flip_edge(h)
        assert state(m) == before
        return
    g = m.flip_edge(h)
    assert m.validate() == []
    assert counts(m) == counts(SPHERE)
    # The flipped edge joins the two vertices that were opposite the old one.
    assert m.find_halfedge(*edge) == -1
    m.flip_edge(g)
    assert m.validate() == []
    assert same_mesh(state(m), before)


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(EDGES))
def test_split_edge_then_collapse_edge_restores_the_mesh(edge):
    m = SPHERE.copy()
    before = state(m)
    v0, e0, f0 = counts(m)
    h = halfedge_between(m, *edge)
    vertex, back = m.split_edge(h)
    assert m.validate() == []
    # Two triangles split: V + 1, E + 3, F + 2; the new vertex at the midpoint.
    assert counts(m) == (v0 + 1, e0 + 3, f0 + 2)
    np.testing.assert_allclose(m.vertices[vertex], (np.array(before[0][edge[0]]) + before[0][edge[1]]) / 2)
    assert m.is_collapse_ok(back, placement="target")
    survivor = m.collapse_edge(back, placement="target")
    assert survivor == edge[1]
    assert m.validate() == []
    assert counts(m) == (v0, e0, f0)
    m.collect_garbage()
    assert state(m)[0] == before[0]
    assert same_mesh(state(m), before)


def test_split_face_makes_three_triangles_at_the_centroid():
    m = hmira.Mesh(TETRA_V, TETRA_F)
    vertex, _ = m.split_face(3)
    assert counts(m) == (5, 9, 6)
    np.testing.assert_allclose(m.vertices[vertex], [1 / 3, 1 / 3, 1 / 3])
    assert m.validate() == []
    vertex, _ = m.split_face(0, position=[0.1, 0.1, 0.0])
    np.testing.assert_allclose(m.vertices[vertex], [0.1, 0.1, 0.0])
    assert m.validate() == []


def test_refused_local_operations_raise_and_change_nothing():
    m = hmira.Mesh(TETRA_V, TETRA_F)
    before = state(m)
    h = halfedge_between(m, 0, 1)
    # A tetrahedron's edge cannot flip (the opposite vertices are joined already) nor
    # collapse (the link condition fails: the result would not be a manifold).
    assert not m.is_flip_ok(h)
    with pytest.raises(ValueError, match="flip_edge"):
        m.flip_edge(h)
    assert not m.is_collapse_ok(h)
    with pytest.raises(ValueError, match="collapse_edge"):
        m.collapse_edge(h)
    with pytest.raises(ValueError, match="halfedge 999 does not exist"):
        m.split_edge(999)
    with pytest.raises(ValueError, match="finite"):
        m.split_edge(h, position=[0, np.nan, 0])
    with pytest.raises(ValueError, match="placement"):
        m.collapse_edge(h, placement="nowhere")
    with pytest.raises(ValueError, match="position exactly when placement='given'"):
        m.collapse_edge(h, placement="given")
    q = cube()
    with pytest.raises(ValueError, match="split_face"):
        q.split_face(0)  # a quad, not a triangle
    assert state(m) == before
    assert m.validate() == []


def test_triangulate_faces_cuts_every_polygon():
    m = cube()
    r = m.triangulate_faces()
    assert r == {"faces_cut": 6, "triangles_added": 6}
    assert m.faces.shape == (12, 3)
    assert m.validate() == []
    assert m.topology().genus == 0 and m.topology().closed
    assert signed_volume(np.array(m.vertices), m.faces) == pytest.approx(1.0)


def test_triangulate_faces_delaunay_joins_the_obtuse_corners():
    # A rhombus whose corners 0 and 2 are obtuse (about 118 degrees): the Delaunay diagonal
    # is 0-2, whatever diagonal ear clipping picked.
    v = np.array([[0, 0, 0], [3, -5, 0], [6, 0, 0], [3, 5, 0]], dtype=float)
    m = hmira.Mesh(v, [[0, 1, 2, 3]])
    assert m.triangulate_faces(delaunay=True) == {"faces_cut": 1, "triangles_added": 1}
    assert all(0 in f and 2 in f for f in m.faces.tolist())
    assert m.validate() == []


def test_fill_hole_closes_the_loop_of_a_boundary_halfedge():
    m = hmira.Mesh(TETRA_V, TETRA_F[:3])  # an open tetrahedron: one triangular hole
    h = halfedge_between(m, 1, 2)  # the hole's side (the removed face ran 1 -> 2 -> 3)
    faces = m.fill_hole(h)
    assert len(faces) == 1
    assert m.topology().closed and m.validate() == []
    with pytest.raises(ValueError, match="fill_hole"):
        m.fill_hole(h)  # no hole there any more
    assert m.topology().closed


def test_fill_holes_on_a_real_mesh_matches_the_cli(data, cli, tmp_path):
    path = data / "meshes" / "elephant-with-holes.off"
    if not path.exists():
        pytest.skip("elephant-with-holes.off not in the test data")
    m = hmira.read_mesh(path)
    loops = m.topology().boundary_loops
    assert loops > 0
    r = m.fill_holes(1000)
    assert r["filled"] == loops and r["skipped"] == 0
    # The elephant has zero-area triangles of its own; anything else would be a defect.
    assert m.topology().boundary_loops == 0 and [p for p in m.validate() if not p.endswith("zero area")] == []
    out = tmp_path / "filled.off"
    run_cli(cli, "fill-holes", path, out, "--max-edges", 1000)
    c = hmira.read_mesh(out)
    assert same_mesh(state(m), state(c))


def test_fill_holes_refuses_a_bad_size_and_changes_nothing():
    m = hmira.Mesh(TETRA_V, TETRA_F[:3])
    before = state(m)
    with pytest.raises(ValueError, match="max_edges must be at least 3"):
        m.fill_holes(2)
    assert state(m) == before


def test_fill_holes_refined_and_faired_matches_the_cli(data, cli, tmp_path):
    path = data / "meshes" / "elephant-with-holes.off"
    if not path.exists():
        pytest.skip("elephant-with-holes.off not in the test data")
    m = hmira.read_mesh(path)
    loops = m.topology().boundary_loops
    r = m.fill_holes(1000, fair="thin-plate")
    assert r["filled"] == loops and r["vertices_added"] > 0 and r["unfaired"] == 0
    assert m.topology().boundary_loops == 0
    out = tmp_path / "faired.off"
    run_cli(cli, "fill-holes", path, out, "--max-edges", 1000, "--fair", "thin-plate")
    assert same_mesh(state(m), state(hmira.read_mesh(out)))
    before = state(m)
    with pytest.raises(ValueError, match="fair must be"):
        m.fill_holes(1000, fair="soap")
    assert state(m) == before


def test_triangulate_faces_on_a_real_mesh_matches_the_cli(data, cli, tmp_path):
    path = data / "meshes" / "corner_poly.off"
    if not path.exists():
        pytest.skip("corner_poly.off not in the test data")
    m = hmira.read_mesh(path)
    m.triangulate_faces()
    assert m.validate() == []
    out = tmp_path / "tri.off"
    run_cli(cli, "triangulate", path, out)
    c = hmira.read_mesh(out)
    assert same_mesh(state(m), state(c))


def test_loop_subdivision_counts_and_schemes():
    m = hmira.Mesh(TETRA_V, TETRA_F)
    r = m.subdivide(scheme="loop", levels=2)
    # Each level: V + E, E * 2 + 3F, F * 4 (4, 6, 4 -> 10, 24, 16 -> 34, 96, 64).
    assert r == {"vertices": 34, "edges": 96, "faces": 64}
    assert counts(m) == (34, 96, 64)
    assert m.validate() == [] and m.topology().genus == 0
    before = state(m)
    with pytest.raises(ValueError, match="unknown scheme 'butterfly'"):
        m.subdivide(scheme="butterfly")
    q = cube()
    with pytest.raises(ValueError, match="loop_subdivide"):
        q.subdivide()  # quads: Loop needs triangles
    assert state(m) == before and counts(q) == (8, 12, 6)


def test_sqrt3_subdivision_counts_positions_and_refusals():
    m = hmira.Mesh(TETRA_V, TETRA_F)
    r = m.subdivide(scheme="sqrt3", levels=2)
    # Each level on a closed mesh: V + F, E + 3F, F * 3 (4, 6, 4 -> 8, 18, 12 -> 20, 54, 36).
    assert r == {"vertices": 20, "edges": 54, "faces": 36}
    assert counts(m) == (20, 54, 36)
    assert m.validate() == [] and m.topology().genus == 0
    # One triangle, two levels: nine triangles; corner a = (0, 0) of (0,0), (27,0), (0,27)
    # goes to (4 u + 19 a + 4 z) / 27 = (4, 4) on the boundary's ternary cubic B-spline.
    t = hmira.Mesh([[0, 0, 0], [27, 0, 0], [0, 27, 0]], [[0, 1, 2]])
    assert t.subdivide(scheme="sqrt3", levels=2) == {"vertices": 10, "edges": 18, "faces": 9}
    np.testing.assert_allclose(t.vertices[0], [4, 4, 0], atol=1e-12)
    q = cube()
    with pytest.raises(ValueError, match="sqrt3_subdivide: face 0 is not a triangle"):
        q.subdivide(scheme="sqrt3")
    assert counts(q) == (8, 12, 6)


def test_catmull_clark_counts_on_a_cube_and_an_open_quad():
    # One level: V + E + F vertices, 2E + (sum of face degrees) edges, (sum of degrees) faces.
    q = cube()
    r = q.subdivide(scheme="catmull-clark")
    assert r == {"vertices": 8 + 12 + 6, "edges": 2 * 12 + 24, "faces": 24}
    assert counts(q) == (26, 48, 24) and q.validate() == [] and q.topology().genus == 0
    # Two levels: 26 + 48 + 24 = 98 vertices, 96 quads (the CLI test's figures).
    assert q.subdivide(scheme="catmull-clark")["faces"] == 96 and counts(q)[0] == 98
    # An open quad: edge points are the edge midpoints, the face point its centre, and each
    # corner moves by the boundary B-spline rule 3/4 v + 1/8 (each boundary neighbour).
    p = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    assert p.subdivide(scheme="catmull-clark") == {"vertices": 9, "edges": 12, "faces": 4}
    expected = sorted([(0.125, 0.125, 0.0), (0.875, 0.125, 0.0), (0.875, 0.875, 0.0), (0.125, 0.875, 0.0),
                       (0.5, 0.0, 0.0), (1.0, 0.5, 0.0), (0.5, 1.0, 0.0), (0.0, 0.5, 0.0), (0.5, 0.5, 0.0)])
    assert sorted(tuple(float(c) for c in v) for v in np.array(p.vertices)) == expected
    assert p.validate() == []


def test_subdivide_on_a_real_mesh_matches_the_cli(data, cli, tmp_path):
    path = data / "meshes" / "bunny00.off"
    if not path.exists():
        pytest.skip("bunny00.off not in the test data")
    m = hmira.read_mesh(path)
    m.subdivide(levels=1)
    out = tmp_path / "sub.off"
    run_cli(cli, "subdivide", path, out, "--scheme", "loop", "-k", 1)
    c = hmira.read_mesh(out)
    np.testing.assert_allclose(canonical(np.array(m.vertices), m.polygons)[0], canonical(np.array(c.vertices), c.polygons)[0], atol=1e-12)
    assert canonical(np.array(m.vertices), m.polygons)[1] == canonical(np.array(c.vertices), c.polygons)[1]


def test_taubin_keeps_the_volume_and_fixed_vertices_stay():
    m = sphere(40)
    v0 = signed_volume(np.array(m.vertices), m.faces)
    fixed = [0, 5, 17]
    where = np.array(m.vertices)[fixed]
    view = m.vertices
    moved = m.taubin_smooth(iterations=10, fixed_vertices=fixed)
    assert moved == m.vertex_count - len(fixed)
    assert abs(signed_volume(np.array(m.vertices), m.faces) / v0 - 1) < 0.01
    assert np.array_equal(np.array(m.vertices)[fixed], where)
    # Smoothing moves positions only: an exported view stays valid and sees them.
    np.testing.assert_array_equal(view, m.vertices)
    assert m.validate() == []


def test_laplacian_smooth_shrinks_and_refuses_bad_options_unchanged():
    m = sphere(24)
    v0 = signed_volume(np.array(m.vertices), m.faces)
    m.smooth("laplacian", iterations=10, lambda_=0.5)
    assert signed_volume(np.array(m.vertices), m.faces) < v0 * 0.99
    before = state(m)
    with pytest.raises(ValueError, match="lambda"):
        m.laplacian_smooth(lambda_=1.5)
    with pytest.raises(ValueError, match="weights"):
        m.taubin_smooth(weights="gaussian")
    with pytest.raises(ValueError, match="vertex 99999 does not exist"):
        m.taubin_smooth(fixed_vertices=[99999])
    with pytest.raises(ValueError, match="method"):
        m.smooth("bilateral")
    assert state(m) == before
