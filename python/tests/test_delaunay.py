"""hmira.delaunay_triangulation: triangle counts against scipy and Euler's formula, the empty
circle property, 2.5-D input, the Voronoi diagram, errors, and agreement with the C++ CLI."""
import numpy as np
import pytest

import hmira
from conftest import canonical, run_cli


def random_points(n, seed=1):
    return np.random.default_rng(seed).random((n, 2))


def hull_size(points):
    from scipy.spatial import ConvexHull

    return len(ConvexHull(points).vertices)


@pytest.mark.parametrize("n", [10, 1000, 20000])
def test_triangle_count_matches_scipy_and_euler(n):
    spatial = pytest.importorskip("scipy.spatial")
    p = random_points(n)
    t = hmira.delaunay_triangulation(p)
    assert t.dtype == np.int32 and t.shape[1] == 3
    assert len(t) == len(spatial.Delaunay(p).simplices)
    assert len(t) == 2 * n - 2 - hull_size(p)


def test_triangles_are_counter_clockwise_and_empty_circle():
    p = random_points(300, seed=7)
    t = hmira.delaunay_triangulation(p)
    a, b, c = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]]
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert np.all(cross > 0)
    # No point strictly inside any triangle's circumcircle (in-circle determinant, with margin).
    for tri in t[::7]:
        pa, pb, pc = p[tri]
        m = np.stack([np.c_[pa - p, ((pa - p) ** 2).sum(1)], np.c_[pb - p, ((pb - p) ** 2).sum(1)],
                      np.c_[pc - p, ((pc - p) ** 2).sum(1)]], axis=1)
        assert np.all(np.linalg.det(m) <= 1e-12)


def test_third_column_is_a_height_not_a_dimension():
    p = random_points(200)
    z = np.random.default_rng(3).random(200)
    np.testing.assert_array_equal(hmira.delaunay_triangulation(np.c_[p, z]), hmira.delaunay_triangulation(p))


def test_duplicates_index_their_first_occurrence():
    p = np.array([[0, 0], [1, 0], [0, 1], [1, 1.1], [1, 0]], dtype=float)
    t = hmira.delaunay_triangulation(p)
    assert len(t) == 2 and 4 not in t


def test_voronoi_vertices_are_circumcentres_and_rays_marked():
    p = random_points(100, seed=5)
    t, vv, ve = hmira.delaunay_triangulation(p, voronoi=True)
    assert vv.shape == (len(t), 2) and ve.dtype == np.int32 and ve.shape[1] == 2
    for i in (0, len(t) // 2, len(t) - 1):
        d = np.linalg.norm(p[t[i]] - vv[i], axis=1)
        np.testing.assert_allclose(d, d[0], rtol=1e-9)
    # One Voronoi edge per Delaunay edge; rays (-1) exactly on the hull edges.
    assert len(ve) == len(t) + len(p) - 1
    assert (ve[:, 1] == -1).sum() == hull_size(p)
    assert ve.min() >= -1 and ve.max() < len(vv)


def test_bad_points_raise_value_error():
    with pytest.raises(ValueError, match="shape"):
        hmira.delaunay_triangulation(np.zeros((5, 4)))
    p = random_points(10)
    p[3, 1] = np.inf
    with pytest.raises(ValueError, match="3"):
        hmira.delaunay_triangulation(p)


def test_matches_the_cli(cli, tmp_path):
    p = np.round(random_points(500, seed=11) * 1000, 3)
    xyz = tmp_path / "p.xyz"
    np.savetxt(xyz, p, fmt="%.3f")
    out = tmp_path / "d.off"
    run_cli(cli, "delaunay", xyz, out, "-q")
    m = hmira.read_mesh(out)
    t = hmira.delaunay_triangulation(np.loadtxt(xyz))
    cv, cf = canonical(np.array(m.vertices)[:, :2], m.polygons)
    pv, pf = canonical(np.loadtxt(xyz), t.tolist())
    np.testing.assert_allclose(pv, cv, atol=1e-9)
    assert pf == cf
